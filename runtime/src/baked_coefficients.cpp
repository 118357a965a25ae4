#include "matc/runtime/baked_coefficients.h"

#include "texel_axis.h"

namespace matc::runtime {

Coefficients coefficients_from_baked(const Rgb& f0, const Rgb& c2, const Rgb& c3) {
  Coefficients coefficients{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double c0 = unit_clamp(f0[c]);  // a NaN F0 reads as 0, as the runtime's other inputs do
    coefficients[c] = {c0, 1.0 - c0, c2[c], c3[c]};
  }
  return coefficients;
}

Coefficients coefficients_from_f0(const Coefficients& zero_f0, const Rgb& f0) {
  Coefficients coefficients{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double c0 = unit_clamp(f0[c]);
    for (std::size_t i = 0; i < 4; ++i)
      coefficients[c][i] = (i == 0 ? c0 : 0.0) + (1.0 - c0) * zero_f0[c][i];
  }
  return coefficients;
}

}  // namespace matc::runtime
