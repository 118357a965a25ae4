// The coefficients of a texel of `matc bake`'s coefficient textures (docs/baking.md), as the
// shaders' matc_coefficients_from_baked computes them: per colour channel c_0 = F0 (clamped to
// [0, 1]), c_1 = 1 - c_0, and c_2, c_3 as sampled from the C2 and C3 textures.
#pragma once

#include "matc/runtime/fresnel.h"

namespace matc::runtime {

Coefficients coefficients_from_baked(const Rgb& f0, const Rgb& c2, const Rgb& c3);

}  // namespace matc::runtime
