// Whether a material's decomposed curve needs the shaders' clamp at 0. The clamp is there for
// truncated curves that dip below 0 (near-black metals fit to -0.2 at some angles); for the rest it
// costs an instruction per channel in every F and Fbar (issue #28: the split-sum pass is 1.11x
// Schlick's with it, 1.07x without). A compiled material's own shader functions leave it out when
// this holds.
#pragma once

#include "matc/runtime/fresnel.h"
#include "matc/runtime/shader_basis.h"

namespace matc {

// Per channel, the margin a curve must keep above 0 at the cosines checked, per unit of
// sum_i |c_i|.
inline constexpr double kNonnegativeMargin = 2e-3;
inline constexpr std::size_t kNonnegativeCosines = 4097;

// True when the basis is a closed form (powers, f82) and every channel of F = sum_i c_i b_i stays
// above kNonnegativeMargin sum_i |c_i| at kNonnegativeCosines even cosines. Why that suffices:
// |b_i'| <= 6 for both closed forms (the largest is powers' b_1 = m^6 at mu = 0), so F dips at
// most 6 sum|c_i| / (2 * 4096) = 7.3e-4 sum|c_i| between the cosines: F > 1.2e-3 sum|c_i|
// everywhere, so direct F needs no clamp. A texel of the preintegrated table is an average of F
// over the lobe's samples (the bake shares samples and non-negative weights across the four
// channels, and its basis table is the closed form sampled), and half-precision storage moves each
// channel by at most 2^-11 of itself, at most 4.9e-4 sum|c_i| in all: every texel, and every
// filtered fetch between texels, keeps sum_i c_i bbar_i >= 0. The fitted bases' polynomials in
// sqrt(mu) have no such slope bound near mu = 0: their materials keep the clamp.
bool fresnel_provably_nonnegative(const runtime::Coefficients& coefficients,
                                  const runtime::ShaderBasis& shader_basis);

}  // namespace matc
