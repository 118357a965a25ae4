// Spectral Fresnel to a linear RGB working space: F_c(mu) = sum_lambda w_c(lambda) F(mu; n, k),
// with w_c from the CIE 1931 2-degree observer under D65, adapted (Bradford) to the space's white,
// converted by its XYZ -> RGB matrix and normalised so that a perfect mirror maps to (1, 1, 1).
#pragma once

#include <vector>

#include "optics/color_space.h"
#include "optics/reflectance_curve.h"
#include "optics/spectrum.h"

namespace matc {

// The integration grid: the CIE tables' 1 nm samples.
inline constexpr int kCieFirstNm = 360;
inline constexpr int kCieLastNm = 830;

// w_c(lambda) on the integration grid (kCieFirstNm + i nm) for a working space: each channel sums
// to 1 (a perfect mirror is the space's white). Computed once per space.
const std::vector<Rgb>& spectral_weights(ColorSpace space);

class SpectralCurve final : public ReflectanceCurve {
 public:
  explicit SpectralCurve(const Spectrum& spectrum, ColorSpace space = kDefaultColorSpace);
  Rgb at(double mu) const override;

 private:
  const std::vector<Rgb>& weights_;  // w_c(lambda) for the working space
  std::vector<ComplexIor> ior_;      // the spectrum resampled on the integration grid
};

}  // namespace matc
