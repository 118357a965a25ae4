#include "bake/bake_inputs.h"

#include <cmath>
#include <thread>

#include <fmt/format.h>

namespace matc {
namespace {

// Where a problem with this map is reported, and the file named in the message.
SourceLocation where(const MapInput& map) {
  return map.location.path.empty() ? SourceLocation{map.resolved.string(), 0, 0} : map.location;
}

void map_error(Diagnostics& diagnostics, const MapInput& map, std::string problem,
               std::string allowed = {}) {
  // A file named from an asset file: say which file, since the location is the asset's.
  const bool from_asset = !map.location.path.empty();
  diagnostics.error(
      where(map), std::string(map_quantity_field(map.quantity)),
      from_asset ? fmt::format("{}: {}", map.resolved.string(), problem) : std::move(problem),
      std::move(allowed));
}

std::optional<MapSamples> load_map(const MapInput& map, Diagnostics& diagnostics) {
  MapSamples samples;
  if (!map.is_file()) {
    samples.constant = *map.constant;
    return samples;
  }
  ImageReadResult read = read_image_map(map.resolved, map.encoding, map.encoding_given);
  if (!read.map) {
    map_error(diagnostics, map, read.error,
              "a PNG or JPEG (8 or 16 bits, 1 to 4 channels) or an "
              "OpenEXR (half or float R, G, B or Y)");
    return std::nullopt;
  }
  // 8- and 16-bit values lie in [0, 1] by construction; OpenEXR values are checked here, with
  // the first offending texel named so an artist can find it.
  const ImageMap& image = *read.map;
  if (!image.is_8_bit() || map.quantity == MapQuantity::n) {
    for (std::size_t texel = 0; texel < image.texel_count(); ++texel) {
      for (std::size_t c = 0; c < 3; ++c) {
        const float value = image.value(texel, c);
        if (map_value_allowed(map.quantity, value)) continue;
        map_error(diagnostics, map,
                  fmt::format("{} at texel ({}, {}) in the {} channel is {}", value,
                              texel % image.width, texel / image.width, "RGB"[c],
                              std::isfinite(value) ? "out of range" : "not a finite number"),
                  fmt::format("values in {}", map_quantity_range(map.quantity)));
        return std::nullopt;
      }
    }
  }
  samples.image = std::move(read.map);
  return samples;
}

}  // namespace

std::optional<BakeInputs> load_bake_inputs(const BakeAsset& asset, Diagnostics& diagnostics) {
  BakeInputs inputs;
  inputs.model = asset.model;
  // The two files decode at once (PNG inflation is single-threaded).
  Diagnostics second_diagnostics;
  std::optional<MapSamples> second;
  std::thread second_reader([&] { second = load_map(asset.second, second_diagnostics); });
  auto first = load_map(asset.first, diagnostics);
  second_reader.join();
  diagnostics.append(second_diagnostics);
  if (!first || !second) return std::nullopt;
  inputs.first = std::move(*first);
  inputs.second = std::move(*second);
  const ImageMap* a = inputs.first.image ? &*inputs.first.image : nullptr;
  const ImageMap* b = inputs.second.image ? &*inputs.second.image : nullptr;
  if (a && b && (a->width != b->width || a->height != b->height)) {
    map_error(diagnostics, asset.second,
              fmt::format("is {} x {} texels, but {} is {} x {}", b->width, b->height,
                          asset.first.resolved.string(), a->width, a->height),
              "two maps of the same size");
    return std::nullopt;
  }
  if (const ImageMap* image = a ? a : b) {
    inputs.width = image->width;
    inputs.height = image->height;
  }
  return inputs;
}

}  // namespace matc
