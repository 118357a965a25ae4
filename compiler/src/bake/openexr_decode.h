// OpenEXR files through the OpenEXR library, from memory (internal to image_map.cpp).
#pragma once

#include <span>

#include "bake/image_map.h"

namespace matc {

// Reads channels R, G, B (A ignored) or Y of a scanline or tiled OpenEXR as float.
ImageReadResult decode_openexr(std::span<const unsigned char> bytes);

}  // namespace matc
