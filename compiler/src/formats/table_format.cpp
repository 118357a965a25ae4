#include "formats/table_format.h"

#include <algorithm>
#include <array>

namespace matc {
namespace {

struct FormatInfo {
  LutFormat format;
  std::string_view name;
  std::string_view extension;
};

constexpr std::array<FormatInfo, 4> kFormats = {{
    {LutFormat::ktx2, "ktx2", ".ktx2"},
    {LutFormat::dds, "dds", ".dds"},
    {LutFormat::raw, "raw", ".bin"},
    {LutFormat::header, "header", ".h"},
}};

static_assert(kFormats.size() == kLutFormats.size(), "every format has its name and extension");

const FormatInfo& info(LutFormat format) {
  return *std::find_if(kFormats.begin(), kFormats.end(),
                       [&](const FormatInfo& f) { return f.format == format; });
}

}  // namespace

std::optional<LutFormat> lut_format_from_extension(std::string_view extension) {
  for (const FormatInfo& f : kFormats) {
    if (f.extension == extension) return f.format;
  }
  return std::nullopt;
}

std::string_view lut_format_name(LutFormat format) {
  return info(format).name;
}

std::string_view lut_precision_name(LutPrecision precision) {
  return precision == LutPrecision::f16 ? "f16" : "f32";
}

std::string_view lut_file_extension(LutFormat format) {
  return info(format).extension;
}

}  // namespace matc
