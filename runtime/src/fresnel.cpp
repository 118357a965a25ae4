#include "matc/runtime/fresnel.h"

#include <algorithm>

namespace matc::runtime {

Rgb evaluate_fresnel(const Coefficients& coefficients, const BasisView& basis, double mu) {
  const auto b = basis.evaluate(mu);
  Rgb result{};
  for (std::size_t channel = 0; channel < 3; ++channel) {
    double sum = 0.0;
    for (std::size_t i = 0; i < kBasisSize; ++i)
      sum += coefficients[channel][i] * b[i];
    // The truncated basis can dip slightly below zero for strong dielectric-like curves.
    result[channel] = std::max(0.0, sum);
  }
  return result;
}

}  // namespace matc::runtime
