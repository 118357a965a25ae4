#include "lut/lut_atlas.h"

#include <algorithm>
#include <stdexcept>

#include "matc/runtime/basis.h"

namespace matc {

LutAtlas side_by_side(std::span<const Lut> layers) {
  if (layers.empty()) throw std::invalid_argument("side_by_side: no layers");
  LutAtlas atlas{layers.front().size, layers.size(), {}};
  const std::size_t row = atlas.size * runtime::kBasisSize;
  atlas.texels.reserve(row * atlas.layers * atlas.size);
  for (const Lut& layer : layers) {
    if (layer.size != atlas.size) throw std::invalid_argument("side_by_side: sizes differ");
  }
  for (std::size_t y = 0; y < atlas.size; ++y) {
    for (const Lut& layer : layers) {
      const auto first = layer.texels.begin() + static_cast<std::ptrdiff_t>(y * row);
      atlas.texels.insert(atlas.texels.end(), first, first + static_cast<std::ptrdiff_t>(row));
    }
  }
  return atlas;
}

}  // namespace matc
