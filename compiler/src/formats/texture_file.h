// A table's texels as a texture file: KTX2, DDS or raw texel bytes, the containers every table
// (the preintegrated, coefficient and LTC tables, a filmed metal's own) is written in. A C++
// header is each table's own (its names and comments), written by its module.
#pragma once

#include <string>

#include "formats/table_format.h"
#include "formats/texel_image.h"

namespace matc::formats {

// The file's bytes at `precision`. Throws std::invalid_argument for LutFormat::header.
std::string encode_texture_file(const TexelImage& image, LutFormat format, LutPrecision precision);

}  // namespace matc::formats
