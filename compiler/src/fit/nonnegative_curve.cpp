#include "fit/nonnegative_curve.h"

#include <array>
#include <cmath>

namespace matc {

bool fresnel_provably_nonnegative(const runtime::Coefficients& coefficients,
                                  const runtime::ShaderBasis& shader_basis) {
  if (!shader_basis.is_closed_form()) return false;
  std::array<double, 3> margins{};
  for (std::size_t channel = 0; channel < 3; ++channel) {
    double total = 0.0;
    for (const double value : coefficients[channel]) {
      if (!std::isfinite(value)) return false;
      total += std::abs(value);
    }
    margins[channel] = kNonnegativeMargin * total;
  }
  for (std::size_t k = 0; k < kNonnegativeCosines; ++k) {
    const double mu = static_cast<double>(k) / static_cast<double>(kNonnegativeCosines - 1);
    const auto b = runtime::evaluate_shader_basis(shader_basis, mu);
    for (std::size_t channel = 0; channel < 3; ++channel) {
      double sum = 0.0;
      for (std::size_t i = 0; i < runtime::kBasisSize; ++i)
        sum += coefficients[channel][i] * b[i];
      if (!(sum >= margins[channel])) return false;
    }
  }
  return true;
}

}  // namespace matc
