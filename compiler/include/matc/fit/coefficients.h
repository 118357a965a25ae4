// The coefficient solve: c_0..c_3 per channel so that sum c_i b_i matches an exact curve.
#pragma once

#include "matc/optics/reflectance_curve.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"

namespace matc {

// Per channel: c_0 = F(mu = 1), c_1 = 1 - c_0 (so F(mu = 0) = 1), and (c_2, c_3) from the 2x2
// system that reproduces F exactly at the basis' two probe cosines.
runtime::Coefficients solve_coefficients(const ReflectanceCurve& curve,
                                         const runtime::BasisView& basis);

}  // namespace matc
