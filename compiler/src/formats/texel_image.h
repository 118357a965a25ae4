// One level of a float texture, as the container writers take it.
#pragma once

#include <cstddef>
#include <span>

namespace matc::formats {

// The preintegrated table (4 channels), the coefficient table (2), a baked coefficient texture.
struct TexelImage {
  std::size_t width = 0;
  std::size_t height = 0;
  std::size_t channels = 4;  // 2 (RG) or 4 (RGBA)
  std::span<const float> texels;
};

}  // namespace matc::formats
