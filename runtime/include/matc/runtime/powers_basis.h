// The closed-form bases: b_1..b_3 are integer powers of m = 1 - mu, so a shader evaluates F with a
// handful of multiplies (docs/accuracy.md, "A basis in closed form"). Both share one shape,
//   b_1 = m^a,   b_2 = mu m^b,   b_3 = b_1 b_2 = mu m^(a+b),
// and differ in the exponents:
// - powers (BasisKind::powers, the default): a = 6, b = 3, fitted to the measured metals;
// - f82 (BasisKind::f82): a = 5, b = 6. F82-tint's curve is F0 + (1 - F0) m^5 - c mu m^6, so b_1
//   and b_2 span every F82-tint curve (Schlick's too) exactly; b_3 is the family's third term.
// b_2 and b_3 are not scaled to a peak of 1: every table matc writes is floating point, so a scale
// would buy no precision and would cost the shader two multiplies.
#pragma once

#include <algorithm>
#include <array>

#include "matc/runtime/basis.h"

namespace matc::runtime {

// The exponents a (b_1 = m^a) and b (b_2 = mu m^b) of a closed form.
struct ClosedFormExponents {
  int edge = 0;
  int lobe = 0;
};
inline constexpr ClosedFormExponents kPowersExponents{6, 3};
inline constexpr ClosedFormExponents kF82Exponents{5, 6};
constexpr ClosedFormExponents closed_form_exponents(BasisKind kind) {
  return kind == BasisKind::f82 ? kF82Exponents : kPowersExponents;
}

// Where the powers basis' b_2 and b_3 peak: mu = 1/4 and 1/10.
inline constexpr double kPowersB2Peak = 27.0 / 256.0;
inline constexpr double kPowersB3Peak = 387420489.0 / 1e10;
// Where the f82 basis' b_2 = mu m^6 and b_3 = mu m^11 peak: mu = 1/7 and 1/12.
inline constexpr double kF82B2Peak = 46656.0 / 823543.0;
inline constexpr double kF82B3Peak = 285311670611.0 / 8916100448256.0;

// b_0..b_3 of the powers basis at mu (clamped to [0, 1]), in the order of the shaders'
// operations. Inline, so that loops over many cosines keep it in registers.
inline std::array<double, kBasisSize> evaluate_powers_basis(double mu) {
  const double x = std::clamp(mu, 0.0, 1.0);
  const double m = 1.0 - x;
  const double m3 = m * m * m;
  const double b1 = m3 * m3;
  const double b2 = x * m3;
  return {1.0, b1, b2, b2 * b1};
}

// b_0..b_3 of the f82 basis at mu (clamped to [0, 1]), in the order of the shaders' operations.
inline std::array<double, kBasisSize> evaluate_f82_basis(double mu) {
  const double x = std::clamp(mu, 0.0, 1.0);
  const double m = 1.0 - x;
  const double m2 = m * m;
  const double m4 = m2 * m2;
  const double b1 = m4 * m;
  const double b2 = x * (m4 * m2);
  return {1.0, b1, b2, b2 * b1};
}

// The bases tabulated at the grid of BasisView (for the table bake and the coefficient solve's
// collocation), computed from the closed forms on first use.
BasisView powers_basis();
BasisView f82_basis();

}  // namespace matc::runtime
