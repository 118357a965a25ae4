// libFuzzer target for `matc bake`'s inputs: the image readers (PNG and JPEG through stb_image,
// OpenEXR through the OpenEXR library) on arbitrary bytes, and, for what decodes, the bake of a
// small map into coefficient textures; the first byte picks sRGB or linear decoding, or the bake
// asset parser on the rest as text. Whatever comes in: a map or a reason, never a crash; decoded
// values stay as the reader promises. Built with -DMATC_BUILD_FUZZERS=ON (clang).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "bake/bake_asset.h"
#include "bake/coefficient_textures.h"
#include "bake/image_map.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t mode = data[0] % 3;
  const std::span<const unsigned char> bytes(data + 1, size - 1);
  if (mode == 2) {
    const matc::BakeAssetResult parsed = matc::parse_bake_asset(
        std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), "fuzz.json");
    if (parsed.asset.has_value() == parsed.diagnostics.has_errors()) __builtin_trap();
    return 0;
  }
  const matc::MapEncoding encoding =
      mode == 0 ? matc::MapEncoding::srgb : matc::MapEncoding::linear;
  const matc::ImageReadResult read = matc::decode_image_map(bytes, encoding, true);
  if (!read.map) {
    if (read.error.empty()) __builtin_trap();
    return 0;
  }
  const matc::ImageMap& map = *read.map;
  if (map.width == 0 || map.height == 0 || map.texel_count() > matc::kMaxImageTexels)
    __builtin_trap();
  if (map.is_8_bit() ? map.codes.size() != 3 * map.texel_count()
                     : map.values.size() != 3 * map.texel_count())
    __builtin_trap();
  // 8- and 16-bit values lie in [0, 1]; OpenEXR values are whatever the file holds.
  bool in_unit_range = true;
  for (std::size_t t = 0; t < map.texel_count(); ++t) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float value = map.value(t, c);
      if (map.format != matc::ImageFileFormat::openexr && !(value >= 0.0f && value <= 1.0f))
        __builtin_trap();
      in_unit_range = in_unit_range && value >= 0.0f && value <= 1.0f;
    }
  }
  if (in_unit_range && map.texel_count() <= 16 * 16) {  // small: many inputs a second
    matc::BakeInputs inputs;
    inputs.width = map.width;
    inputs.height = map.height;
    inputs.first.image = map;
    inputs.second.image = map;
    matc::BakeOptions options;
    options.threads = 1;
    const matc::BakedCoefficients baked = matc::bake_coefficients(inputs, options);
    const matc::CoefficientLevel& top = baked.levels.back();
    if (top.width != 1 || top.height != 1) __builtin_trap();
    for (const float value : top.c2)
      if (!std::isfinite(value)) __builtin_trap();
  }
  return 0;
}
