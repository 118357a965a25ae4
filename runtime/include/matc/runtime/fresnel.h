// Evaluating the decomposed Fresnel reflectance from compiled coefficients.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>

#include "matc/runtime/basis.h"
#include "matc/runtime/shader_basis.h"

namespace matc::runtime {

using Rgb = std::array<double, 3>;
// c_0..c_3 of one colour channel.
using ChannelCoefficients = std::array<double, kBasisSize>;
// One row of coefficients per channel: R, G, B.
using Coefficients = std::array<ChannelCoefficients, 3>;

// max(0, sum_i c_i v_i) per channel: F when v is the basis at a cosine, Fbar when v is the
// preintegrated basis. The clamp matters where the truncated basis dips below zero. Inline, so
// that loops over many cosines keep it in registers.
inline Rgb combine(const Coefficients& coefficients, const std::array<double, kBasisSize>& values) {
  Rgb result{};
  for (std::size_t channel = 0; channel < 3; ++channel) {
    double sum = 0.0;
    for (std::size_t i = 0; i < kBasisSize; ++i)
      sum += coefficients[channel][i] * values[i];
    result[channel] = std::max(0.0, sum);
  }
  return result;
}

// F(mu) = max(0, sum_i c_i b_i(mu)) per channel with the tabulated basis (what the coefficient
// solve sees).
Rgb evaluate_fresnel(const Coefficients& coefficients, const BasisView& basis, double mu);
// ... and with the shaders' polynomial basis: what the generated shaders compute.
Rgb evaluate_fresnel(const Coefficients& coefficients, const ShaderBasis& basis, double mu);
// The same at every cosine of `mu`, into `rgb` (R, G, B per cosine: 3 * mu.size() values), the
// same values in one loop, faster than a call per cosine (bench/fresnel_eval_benchmark.cpp).
void evaluate_fresnel(const Coefficients& coefficients, const ShaderBasis& basis,
                      std::span<const double> mu, std::span<double> rgb);

}  // namespace matc::runtime
