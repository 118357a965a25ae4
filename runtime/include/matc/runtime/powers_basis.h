// The powers basis (BasisKind::powers, the default): b_1..b_3 in closed form, integer powers of
// m = 1 - mu, so a shader evaluates F with a handful of multiplies (docs/accuracy.md, "A basis in
// closed form"):
//   b_1 = m^6,   b_2 = mu m^3,   b_3 = mu m^9 = b_2 b_1.
// Unlike the fitted bases, b_2 and b_3 are not scaled to a peak of 1 (they peak at 27/256 and
// 9^9/10^10): every table matc writes is floating point, so a scale would buy no precision and
// would cost the shader two multiplies.
#pragma once

#include <algorithm>
#include <array>

#include "matc/runtime/basis.h"

namespace matc::runtime {

// Where b_2 and b_3 peak: mu = 1/4 and 1/10.
inline constexpr double kPowersB2Peak = 27.0 / 256.0;
inline constexpr double kPowersB3Peak = 387420489.0 / 1e10;

// b_0..b_3 at mu (clamped to [0, 1]), in the order of the shaders' operations. Inline, so that
// loops over many cosines keep it in registers.
inline std::array<double, kBasisSize> evaluate_powers_basis(double mu) {
  const double x = std::clamp(mu, 0.0, 1.0);
  const double m = 1.0 - x;
  const double m3 = m * m * m;
  const double b1 = m3 * m3;
  const double b2 = x * m3;
  return {1.0, b1, b2, b2 * b1};
}

// The basis tabulated at the grid of BasisView (for the table bake and the coefficient solve's
// collocation), computed from the closed form on first use.
BasisView powers_basis();

}  // namespace matc::runtime
