// The coefficient solve: c_0..c_3 per channel so that sum c_i b_i matches an exact curve.
#pragma once

#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/shader_basis.h"
#include "optics/reflectance_curve.h"

namespace matc {

// Both solves fix c_0 = F(mu = 1) and c_1 = 1 - c_0, so F(mu = 0) = 1 and F(1) = F0 hold exactly
// (b_2, b_3 vanish at both ends); they differ in how (c_2, c_3) are chosen. A curve that does not
// reach 1 at grazing (ReflectanceCurve::grazing_value: a metal seen through a coat) keeps c_0 =
// F(1); the probe solve pins c_1 = F(0) - c_0, the minimax solve fits c_1 with (c_2, c_3).

// Collocation (the authors): the 2x2 system that reproduces F exactly at the basis' two probes.
runtime::Coefficients solve_coefficients_at_probes(const ReflectanceCurve& curve,
                                                   const runtime::BasisView& basis);

// Near-minimax: (c_2, c_3) that minimise the largest |F - exact| over kMinimaxCosines cosines,
// measured on the basis as the shaders evaluate it (`shader_basis`).
inline constexpr std::size_t kMinimaxCosines = 401;
runtime::Coefficients solve_coefficients_minimax(const ReflectanceCurve& curve,
                                                 const runtime::ShaderBasis& shader_basis);

// Least squares over the same cosines (uniform weights): the solve minimax starts from.
runtime::Coefficients solve_coefficients_least_squares(const ReflectanceCurve& curve,
                                                       const runtime::ShaderBasis& shader_basis);

// The basis' own solve: at its probes for the paper basis, near-minimax for the conductor basis.
runtime::Coefficients solve_coefficients(const ReflectanceCurve& curve,
                                         const runtime::BasisView& basis);

}  // namespace matc
