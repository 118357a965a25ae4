// The preintegrated table as a C++ header (docs/lut.md): its texels as constexpr arrays.
#pragma once

#include <string>

#include "lut/lut_files.h"

namespace matc {

// Texels rounded through half precision when `precision` is f16, so that they equal what the
// texture formats store.
std::string encode_lut_header(const BakedLut& baked, LutPrecision precision);

}  // namespace matc
