#include "bake/image_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <stb/stb_image.h>

#include "base/content_hash.h"
#include "material/parse.h"  // load_file
#include "openexr_decode.h"

namespace matc {
namespace {

constexpr std::array<unsigned char, 8> kPngSignature = {0x89, 'P',  'N',  'G',
                                                        0x0D, 0x0A, 0x1A, 0x0A};
constexpr std::array<unsigned char, 3> kJpegSignature = {0xFF, 0xD8, 0xFF};
constexpr std::array<unsigned char, 4> kOpenExrSignature = {0x76, 0x2F, 0x31, 0x01};

template <std::size_t N>
bool starts_with(std::span<const unsigned char> bytes, const std::array<unsigned char, N>& magic) {
  return bytes.size() >= N && std::equal(magic.begin(), magic.end(), bytes.begin());
}

ImageReadResult failure(std::string reason) {
  return {std::nullopt, std::move(reason)};
}

// stb_image decodes what it can of a JPEG that ends early and fills the rest; a complete one
// ends with the end-of-image marker (some writers pad after it).
bool jpeg_has_end_marker(std::span<const unsigned char> bytes) {
  std::size_t end = bytes.size();
  while (end > 2 && bytes[end - 1] == 0x00)
    --end;
  return end >= 4 && bytes[end - 2] == 0xFF && bytes[end - 1] == 0xD9;
}

// The width and height a PNG's header (its IHDR chunk, first after the signature) claims. stb_image
// refuses a header whose texels would not fit its own 1 GiB bound and then reports only "unknown
// image type"; reading the two numbers first lets the size limit speak instead.
std::optional<std::pair<std::size_t, std::size_t>> png_header_size(
    std::span<const unsigned char> bytes) {
  constexpr std::size_t kIhdrEnd = 24;  // signature (8), length (4), type (4), width, height
  if (bytes.size() < kIhdrEnd || !std::equal(bytes.begin() + 12, bytes.begin() + 16, "IHDR"))
    return std::nullopt;
  const auto big_endian = [&](std::size_t offset) {
    std::size_t value = 0;
    for (std::size_t i = 0; i < 4; ++i)
      value = (value << 8) | bytes[offset + i];
    return value;
  };
  return std::pair{big_endian(16), big_endian(20)};
}

struct StbFree {
  void operator()(void* pixels) const { stbi_image_free(pixels); }
};

ImageReadResult decode_with_stb(std::span<const unsigned char> bytes, ImageFileFormat format,
                                MapEncoding encoding) {
  const std::string_view kind = image_file_format_name(format);
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    return failure(fmt::format("is too large for a {} reader", kind));
  if (format == ImageFileFormat::png) {
    if (const auto claimed = png_header_size(bytes)) {
      if (auto too_large = image_size_limit_failure(claimed->first, claimed->second))
        return failure(std::move(*too_large));
    }
  }
  const auto* data = bytes.data();
  const int length = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(data, length, &width, &height, &channels) == 0)
    return failure(fmt::format("is not a readable {} ({})", kind, stbi_failure_reason()));
  const auto w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
  if (auto too_large = image_size_limit_failure(w, h)) return failure(std::move(*too_large));
  if (format == ImageFileFormat::jpeg && !jpeg_has_end_marker(bytes))
    return failure("is a truncated JPEG (no end-of-image marker)");
  const bool sixteen_bit = stbi_is_16_bit_from_memory(data, length) != 0;
  ImageMap map;
  map.width = w;
  map.height = h;
  map.format = format;
  map.file_channels = channels;
  map.bits = sixteen_bit ? 16 : 8;
  map.encoding = encoding;
  // Grey, grey + alpha, RGB, RGBA: the colour channels' offsets in a texel.
  const std::array<int, 3> source =
      channels < 3 ? std::array<int, 3>{0, 0, 0} : std::array<int, 3>{0, 1, 2};
  const std::size_t texels = w * h;
  const auto stride = static_cast<std::size_t>(channels);
  const auto decode = [&](double encoded) {
    return encoding == MapEncoding::srgb ? srgb_to_linear(encoded) : encoded;
  };
  if (sixteen_bit) {
    const std::unique_ptr<stbi_us, StbFree> pixels(
        stbi_load_16_from_memory(data, length, &width, &height, &channels, 0));
    if (!pixels)
      return failure(fmt::format("is not a readable {} ({})", kind, stbi_failure_reason()));
    map.values.resize(texels * 3);
    for (std::size_t t = 0; t < texels; ++t)
      for (std::size_t c = 0; c < 3; ++c)
        map.values[3 * t + c] =
            static_cast<float>(decode(pixels.get()[t * stride + source[c]] / 65535.0));
    return {std::move(map), {}};
  }
  const std::unique_ptr<stbi_uc, StbFree> pixels(
      stbi_load_from_memory(data, length, &width, &height, &channels, 0));
  if (!pixels)
    return failure(fmt::format("is not a readable {} ({})", kind, stbi_failure_reason()));
  map.codes.resize(texels * 3);
  for (std::size_t t = 0; t < texels; ++t)
    for (std::size_t c = 0; c < 3; ++c)
      map.codes[3 * t + c] = pixels.get()[t * stride + source[c]];
  map.code_values.resize(256);
  for (std::size_t code = 0; code < 256; ++code)
    map.code_values[code] = static_cast<float>(decode(static_cast<double>(code) / 255.0));
  return {std::move(map), {}};
}

}  // namespace

std::optional<std::string> image_size_limit_failure(std::size_t width, std::size_t height) {
  if (width <= kMaxImageSide && height <= kMaxImageSide && width * height <= kMaxImageTexels)
    return std::nullopt;
  return fmt::format(
      "{} x {} texels is more than a map may hold (at most {} per side and {} in all)", width,
      height, kMaxImageSide, kMaxImageTexels);
}

std::string_view map_encoding_name(MapEncoding encoding) {
  return encoding == MapEncoding::srgb ? "srgb" : "linear";
}

std::optional<MapEncoding> map_encoding_from_name(std::string_view name) {
  if (name == "srgb") return MapEncoding::srgb;
  if (name == "linear") return MapEncoding::linear;
  return std::nullopt;
}

std::string_view image_file_format_name(ImageFileFormat format) {
  switch (format) {
    case ImageFileFormat::png:
      return "PNG";
    case ImageFileFormat::jpeg:
      return "JPEG";
    case ImageFileFormat::openexr:
      break;
  }
  return "OpenEXR";
}

double srgb_to_linear(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

ImageReadResult decode_image_map(std::span<const unsigned char> bytes, MapEncoding encoding,
                                 bool encoding_given) {
  if (bytes.empty()) return failure("is empty");
  ImageReadResult result;
  if (starts_with(bytes, kPngSignature)) {
    result = decode_with_stb(bytes, ImageFileFormat::png, encoding);
  } else if (starts_with(bytes, kJpegSignature)) {
    result = decode_with_stb(bytes, ImageFileFormat::jpeg, encoding);
  } else if (!starts_with(bytes, kOpenExrSignature)) {
    return failure("is not a PNG, JPEG or OpenEXR file (unknown signature)");
  } else if (encoding_given && encoding == MapEncoding::srgb) {
    return failure("is an OpenEXR file, which holds linear values: it cannot be sRGB-encoded");
  } else {
    result = decode_openexr(bytes);
  }
  if (result.map) {
    result.map->source_hash =
        hash_of_bytes({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  }
  return result;
}

ImageReadResult read_image_map(const std::filesystem::path& file, MapEncoding encoding,
                               bool encoding_given) {
  const LoadedFile loaded = load_file(file, kMaxImageFileBytes);
  if (!loaded.bytes) return failure(fmt::format("cannot read: {}", loaded.error));
  const auto* data = reinterpret_cast<const unsigned char*>(loaded.bytes->data());
  return decode_image_map({data, loaded.bytes->size()}, encoding, encoding_given);
}

}  // namespace matc
