// An asset's maps read and checked for baking: both files decoded, the same size, every value in
// its quantity's range. Problems are reported as "<file>: <problem>" at the place that named the
// file (the asset file's line and column, or the file itself for command-line maps).
#pragma once

#include <cstddef>
#include <optional>

#include "bake/bake_asset.h"
#include "bake/image_map.h"
#include "base/diagnostics.h"

namespace matc {

// One map ready to sample: a decoded image or a constant.
struct MapSamples {
  std::optional<ImageMap> image;
  runtime::Rgb constant{};
  bool is_image() const { return image.has_value(); }
  // 8-bit image or constant: few distinct values per channel, each solved once.
  bool is_quantised() const { return !image || image->is_8_bit(); }
  float value(std::size_t texel, std::size_t channel) const {
    return image ? image->value(texel, channel) : static_cast<float>(constant[channel]);
  }
};

struct BakeInputs {
  BakeModel model = BakeModel::artistic;
  MapSamples first;       // reflectivity or n
  MapSamples second;      // edge tint or k
  std::size_t width = 1;  // the maps' size (1 x 1 when both are constants)
  std::size_t height = 1;
};

std::optional<BakeInputs> load_bake_inputs(const BakeAsset& asset, Diagnostics& diagnostics);

}  // namespace matc
