// The coefficients of a texel of `matc bake`'s coefficient textures (docs/baking.md), as the
// shaders' matc_coefficients_from_baked computes them: per colour channel c_0 = F0 (clamped to
// [0, 1]), c_1 = 1 - c_0, and c_2, c_3 as sampled from the C2 and C3 textures.
#pragma once

#include "matc/runtime/fresnel.h"

namespace matc::runtime {

Coefficients coefficients_from_baked(const Rgb& f0, const Rgb& c2, const Rgb& c3);

// A textured metal of Schlick's curve at a pixel, as the shaders' matc_coefficients_from_f0
// computes it: Schlick's curve is linear in F0, and so are its coefficients, so per channel
// F0 (1, 0, 0, 0) + (1 - F0) times `zero_f0`, the curve's coefficients at F0 = 0 (F0 clamped to
// [0, 1]; NaN reads as 0).
Coefficients coefficients_from_f0(const Coefficients& zero_f0, const Rgb& f0);

}  // namespace matc::runtime
