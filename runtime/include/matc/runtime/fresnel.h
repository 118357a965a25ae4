// Evaluating the decomposed Fresnel reflectance from compiled coefficients.
#pragma once

#include <array>

#include "matc/runtime/basis.h"
#include "matc/runtime/shader_basis.h"

namespace matc::runtime {

using Rgb = std::array<double, 3>;
// c_0..c_3 of one colour channel.
using ChannelCoefficients = std::array<double, kBasisSize>;
// One row of coefficients per channel: R, G, B.
using Coefficients = std::array<ChannelCoefficients, 3>;

// max(0, sum_i c_i v_i) per channel: F when v is the basis at a cosine, Fbar when v is the
// preintegrated basis. The clamp matters where the truncated basis dips below zero.
Rgb combine(const Coefficients& coefficients, const std::array<double, kBasisSize>& values);

// F(mu) = max(0, sum_i c_i b_i(mu)) per channel with the tabulated basis (what the coefficient
// solve sees).
Rgb evaluate_fresnel(const Coefficients& coefficients, const BasisView& basis, double mu);
// ... and with the shaders' polynomial basis: what the generated shaders compute.
Rgb evaluate_fresnel(const Coefficients& coefficients, const ShaderBasis& basis, double mu);

}  // namespace matc::runtime
