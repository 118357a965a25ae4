// One encoder per container format; lut_files.cpp and coefficient_table_files.cpp dispatch
// between them.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "matc/lut/lut_files.h"

namespace matc::lut_writers {

// One level of a float texture: the preintegrated table (4 channels) or the coefficient table (2).
struct TexelImage {
  std::size_t width = 0;
  std::size_t height = 0;
  std::size_t channels = 4;  // 2 (RG) or 4 (RGBA)
  std::span<const float> texels;
};

// Level 0 first, each level half the size of the one before (rounded down, at least 1): the
// coefficient textures of `matc bake` carry full mip chains, the tables one level.
std::string encode_ktx2(std::span<const TexelImage> levels, LutPrecision precision);
std::string encode_dds(std::span<const TexelImage> levels, LutPrecision precision);
std::string encode_header(const BakedLut& baked, LutPrecision precision);

}  // namespace matc::lut_writers
