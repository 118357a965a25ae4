// The file formats matc writes float tables and textures in (the preintegrated table, the
// coefficient and LTC tables, baked coefficient textures), and their texel precision.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace matc {

enum class LutFormat { ktx2, dds, raw, header };
enum class LutPrecision { f16, f32 };

inline constexpr std::array<LutFormat, 4> kLutFormats = {LutFormat::ktx2, LutFormat::dds,
                                                         LutFormat::raw, LutFormat::header};
inline constexpr std::array<LutPrecision, 2> kLutPrecisions = {LutPrecision::f16,
                                                               LutPrecision::f32};

// "ktx2", "dds", "raw", "header" (options read them through options/option_names.h).
std::string_view lut_format_name(LutFormat format);
std::string_view lut_precision_name(LutPrecision precision);  // "f16", "f32"
std::optional<LutFormat> lut_format_from_extension(std::string_view extension);
std::string_view lut_file_extension(LutFormat format);  // ".ktx2", ".dds", ".bin", ".h"

}  // namespace matc
