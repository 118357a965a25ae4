// Texture maps read for `matc bake`: PNG and JPEG through stb_image (8 and 16 bits, 1 to 4
// channels), OpenEXR through the OpenEXR library (half, float and uint channels R, G, B or Y).
// Every map becomes three linear channels; alpha is ignored (a coefficient texture has no
// coverage; opacity stays in the engine's own textures). docs/baking.md lists what is accepted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace matc {

// How 8- and 16-bit values encode the quantity: sRGB (colour maps: reflectivity and edge tint
// are colours artists paint) or linear (data maps). OpenEXR always holds linear values.
enum class MapEncoding { srgb, linear };
std::string_view map_encoding_name(MapEncoding encoding);
std::optional<MapEncoding> map_encoding_from_name(std::string_view name);

enum class ImageFileFormat { png, jpeg, openexr };
std::string_view image_file_format_name(ImageFileFormat format);

// Bounds on what is read, so memory stays bounded (docs/baking.md states the bake's footprint).
inline constexpr std::size_t kMaxImageSide = 16384;
inline constexpr std::size_t kMaxImageTexels = std::size_t{1} << 24;           // 4096 x 4096
inline constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t{1} << 30;  // 1 GiB

// Why a map of width x height texels cannot be read (the bounds above), or nothing if it can.
std::optional<std::string> image_size_limit_failure(std::size_t width, std::size_t height);

struct ImageMap {
  std::size_t width = 0;
  std::size_t height = 0;
  ImageFileFormat format = ImageFileFormat::png;
  int file_channels = 0;  // 1 (grey), 2 (grey, alpha), 3 (RGB) or 4 (RGBA) as stored
  int bits = 8;           // 8 or 16 for PNG and JPEG; 16 (half) or 32 for OpenEXR
  MapEncoding encoding = MapEncoding::linear;
  // 8-bit files keep their codes (3 per texel, grey replicated) and a decoding table: at most 256
  // distinct values per channel, which the bake solves once each.
  std::vector<std::uint8_t> codes;
  std::vector<float> code_values;  // 256 entries: the linear value of each code
  // Other files: linear values, 3 per texel.
  std::vector<float> values;
  std::string source_hash;  // XXH3 of the file's bytes (content_hash.h), for manifests

  std::size_t texel_count() const { return width * height; }
  bool is_8_bit() const { return !codes.empty(); }
  // The linear value of a texel's channel.
  float value(std::size_t texel, std::size_t channel) const {
    return is_8_bit() ? code_values[codes[3 * texel + channel]] : values[3 * texel + channel];
  }
};

// The map, or why it cannot be read ("truncated PNG: ...", "3000 x 9000 texels is more than
// ..."); the caller names the file. `encoding` applies to 8- and 16-bit files; an OpenEXR given
// an sRGB encoding explicitly is an error (`encoding_given`).
struct ImageReadResult {
  std::optional<ImageMap> map;
  std::string error;
};
ImageReadResult decode_image_map(std::span<const unsigned char> bytes, MapEncoding encoding,
                                 bool encoding_given = false);
ImageReadResult read_image_map(const std::filesystem::path& file, MapEncoding encoding,
                               bool encoding_given = false);

// The sRGB transfer function (IEC 61966-2-1), decoding: encoded [0, 1] -> linear [0, 1].
double srgb_to_linear(double encoded);

}  // namespace matc
