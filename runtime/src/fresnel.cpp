#include "matc/runtime/fresnel.h"

#include <algorithm>

namespace matc::runtime {

Rgb combine(const Coefficients& coefficients, const std::array<double, kBasisSize>& values) {
  Rgb result{};
  for (std::size_t channel = 0; channel < 3; ++channel) {
    double sum = 0.0;
    for (std::size_t i = 0; i < kBasisSize; ++i)
      sum += coefficients[channel][i] * values[i];
    result[channel] = std::max(0.0, sum);
  }
  return result;
}

Rgb evaluate_fresnel(const Coefficients& coefficients, const BasisView& basis, double mu) {
  return combine(coefficients, basis.evaluate(mu));
}

Rgb evaluate_fresnel(const Coefficients& coefficients, const ShaderBasis& basis, double mu) {
  return combine(coefficients, evaluate_shader_basis(basis, mu));
}

}  // namespace matc::runtime
