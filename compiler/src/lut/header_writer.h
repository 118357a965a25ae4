// The preintegrated table as a C++ header (docs/lut.md): its texels as constexpr arrays.
#pragma once

#include <span>
#include <string>

#include "lut/lut_files.h"

namespace matc {

// Texels rounded through half precision when `precision` is f16, so that they equal what the
// texture formats store.
std::string encode_lut_header(const BakedLut& baked, LutPrecision precision);

// A per-material build's table (--basis auto): `atlas` (the layers as stored, side by side, each
// kSize wide), the layers' bakes in the same order for their energy tables.
std::string encode_layered_lut_header(std::span<const BakedLut> layers, const LutAtlas& atlas,
                                      LutPrecision precision);

}  // namespace matc
