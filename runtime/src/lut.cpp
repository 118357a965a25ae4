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
  return sample_bilinear<kBasisSize>(lut, lut.size, lut_u_from_ndotv(ndotv), roughness);
}

Rgb evaluate_fbar(const Coefficients& coefficients, const LutView& lut, double ndotv,
                  double roughness) {
  return combine(coefficients, sample_lut(lut, ndotv, roughness));
}

}  // namespace matc::runtime
