// How far an approximation is from the exact curve, per channel, over mu in [0, 1].
#pragma once

#include <cstddef>

#include "matc/optics/reflectance_curve.h"
#include "matc/runtime/basis_polynomial.h"
#include "matc/runtime/fresnel.h"

namespace matc {

// Errors are measured at this many cosines, mu_j = j / (count - 1). The count is odd and not
// 1 + a multiple of the basis grid's 999 intervals, so most points fall between basis samples and
// the interpolation the shaders do is part of what is measured.
inline constexpr std::size_t kAccuracySamples = 2001;

struct ErrorStats {
  Rgb max_abs{};  // max over mu of |approximation - exact|
  Rgb rms{};      // root mean square over the same points
};

// The largest of the three channels' values: the "worst channel" the tables report.
double worst_channel(const Rgb& values);

struct FitAccuracy {
  std::size_t samples = kAccuracySamples;
  ErrorStats decomposition;  // ours: max(0, sum c_i b_i)
  ErrorStats schlick;        // Schlick with the exact F0
  ErrorStats f82_tint;       // Hoffman's F82-tint with the exact F0 and F(1/7)
};

FitAccuracy measure_accuracy(const ReflectanceCurve& curve,
                             const runtime::Coefficients& coefficients,
                             const runtime::BasisPolynomial& shader_basis,
                             std::size_t samples = kAccuracySamples);

}  // namespace matc
