// DDS files of float textures (docs/lut.md has the layout matc writes).
#pragma once

#include <span>
#include <string>

#include "formats/table_format.h"
#include "formats/texel_image.h"

namespace matc::formats {

// Level 0 first, each level half the size of the one before (rounded down, at least 1): the
// coefficient textures of `matc bake` carry full mip chains, the tables one level.
std::string encode_dds(std::span<const TexelImage> levels, LutPrecision precision);

}  // namespace matc::formats
