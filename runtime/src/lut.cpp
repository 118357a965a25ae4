#include "matc/runtime/lut.h"

#include <algorithm>
#include <cmath>

#include "texel_axis.h"

namespace matc::runtime {

double lut_u_from_ndotv(double ndotv) {
  return std::sqrt(std::clamp(ndotv, 0.0, 1.0));
}
double lut_ndotv_from_u(double u) {
  return u * u;
}

std::array<float, kBasisSize> LutView::texel(std::size_t x, std::size_t y) const {
  const std::size_t offset = (y * size + x) * kBasisSize;
  return {texels[offset], texels[offset + 1], texels[offset + 2], texels[offset + 3]};
}

std::array<double, kBasisSize> sample_lut(const LutView& lut, double ndotv, double roughness) {
  const auto [x, tx] = texel_axis_position(lut_u_from_ndotv(ndotv), lut.size);
  const auto [y, ty] = texel_axis_position(roughness, lut.size);
  const auto t00 = lut.texel(x, y);
  const auto t10 = lut.texel(x + 1, y);
  const auto t01 = lut.texel(x, y + 1);
  const auto t11 = lut.texel(x + 1, y + 1);
  std::array<double, kBasisSize> result{};
  for (std::size_t i = 0; i < kBasisSize; ++i) {
    const double bottom = t00[i] + tx * (t10[i] - t00[i]);
    const double top = t01[i] + tx * (t11[i] - t01[i]);
    result[i] = bottom + ty * (top - bottom);
  }
  return result;
}

Rgb evaluate_fbar(const Coefficients& coefficients, const LutView& lut, double ndotv,
                  double roughness) {
  return combine(coefficients, sample_lut(lut, ndotv, roughness));
}

}  // namespace matc::runtime
