#include "lut/energy.h"

namespace matc {

std::array<double, runtime::kBasisSize> basis_hemispherical_averages(
    const runtime::BasisView& basis) {
  std::array<double, runtime::kBasisSize> averages{};
  for (std::size_t j = 0; j + 1 < basis.samples(); ++j) {
    const double a = basis.mu_at(j);
    const double b = basis.mu_at(j + 1);
    const auto fa = basis.at_index(j);
    const auto fb = basis.at_index(j + 1);
    // Integral of the linear interpolant times mu over [a, b].
    for (std::size_t i = 0; i < runtime::kBasisSize; ++i) {
      averages[i] += 2.0 * (b - a) / 6.0 * (fa[i] * (2.0 * a + b) + fb[i] * (a + 2.0 * b));
    }
  }
  return averages;
}

runtime::Rgb average_fresnel(const runtime::Coefficients& coefficients,
                             const std::array<double, runtime::kBasisSize>& averages) {
  runtime::Rgb result{};
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < runtime::kBasisSize; ++i) {
      result[c] += coefficients[c][i] * averages[i];
    }
  }
  return result;
}

std::vector<double> average_albedo(const Lut& lut) {
  // With mu = u^2: 2 * integral E mu dmu = 4 * integral_0^1 E(u) u^3 du.
  const runtime::LutView view = lut.view();
  const double h = 1.0 / static_cast<double>(lut.size - 1);
  std::vector<double> result(lut.size);
  for (std::size_t y = 0; y < lut.size; ++y) {
    double sum = 0.0;
    for (std::size_t x = 0; x < lut.size; ++x) {
      const double u = static_cast<double>(x) * h;
      const double end_weight = (x == 0 || x + 1 == lut.size) ? 0.5 : 1.0;
      sum += end_weight * view.texel(x, y)[0] * u * u * u;
    }
    result[y] = 4.0 * h * sum;
  }
  return result;
}

}  // namespace matc
