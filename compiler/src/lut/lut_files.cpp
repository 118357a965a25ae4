#include "matc/lut/lut_files.h"

#include <algorithm>

#include <fmt/format.h>

#include "lut_writers.h"
#include "matc/lut/energy.h"
#include "matc/version.h"
#include "texel_bytes.h"

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

lut_writers::TexelImage image_of(const Lut& lut) {
  return {lut.size, lut.size, runtime::kBasisSize, lut.texels};
}

const FormatInfo& info(LutFormat format) {
  return *std::find_if(kFormats.begin(), kFormats.end(),
                       [&](const FormatInfo& f) { return f.format == format; });
}

}  // namespace

std::vector<std::string> lut_format_names() {
  std::vector<std::string> names;
  for (const FormatInfo& f : kFormats)
    names.emplace_back(f.name);
  return names;
}

std::optional<LutFormat> lut_format_from_name(std::string_view name) {
  for (const FormatInfo& f : kFormats) {
    if (f.name == name) return f.format;
  }
  return std::nullopt;
}

std::optional<LutFormat> lut_format_from_extension(std::string_view extension) {
  for (const FormatInfo& f : kFormats) {
    if (f.extension == extension) return f.format;
  }
  return std::nullopt;
}

std::optional<LutPrecision> lut_precision_from_name(std::string_view name) {
  if (name == "f16") return LutPrecision::f16;
  if (name == "f32") return LutPrecision::f32;
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

Lut stored_as(Lut lut, LutPrecision precision) {
  if (precision == LutPrecision::f16) {
    for (float& value : lut.texels)
      value = lut_bytes::round_to_half(value);
  }
  return lut;
}

BakedLut bake_lut(const runtime::BasisView& basis, const LutOptions& options) {
  BakedLut baked;
  baked.lut = preintegrate_lut(basis, options);
  baked.basis = basis.kind;
  baked.average_albedo = average_albedo(baked.lut);
  baked.basis_averages = basis_hemispherical_averages(basis);
  return baked;
}

std::string encode_lut(const BakedLut& baked, LutFormat format, LutPrecision precision) {
  switch (format) {
    case LutFormat::ktx2: {
      const lut_writers::TexelImage image = image_of(baked.lut);
      return lut_writers::encode_ktx2({&image, 1}, precision);
    }
    case LutFormat::dds: {
      const lut_writers::TexelImage image = image_of(baked.lut);
      return lut_writers::encode_dds({&image, 1}, precision);
    }
    case LutFormat::raw:
      return lut_bytes::texel_bytes(baked.lut.texels, precision);
    case LutFormat::header:
      return lut_writers::encode_header(baked, precision);
  }
  return {};
}

nlohmann::ordered_json roughness_table_layout(std::string_view columns_from_ndotv,
                                              std::string_view channels) {
  return {
      {"rows", "roughness (perceptual; GGX alpha = roughness^2), first row = 0"},
      {"columns", fmt::format("u = {}, first column = 0", columns_from_ndotv)},
      {"texel_centres", "texel (x, y) holds u = x / (size - 1), roughness = y / (size - 1)"},
      {"sampling", "linear filtering, clamp to edge, at (u * (size - 1) + 0.5) / size per axis"},
      {"raw", fmt::format("row-major, {} interleaved, little-endian, tightly packed", channels)}};
}

nlohmann::ordered_json lut_manifest(const BakedLut& baked, LutFormat format,
                                    LutPrecision precision) {
  const Lut& lut = baked.lut;
  nlohmann::ordered_json manifest;
  manifest["matc_version"] = kVersion;
  manifest["kind"] = "matc preintegrated Fresnel basis table";
  manifest["format"] = lut_format_name(format);
  manifest["precision"] = lut_precision_name(precision);
  manifest["size"] = {lut.size, lut.size};
  manifest["samples_per_texel"] = lut.samples;
  manifest["basis"] = runtime::basis_name(baked.basis);
  manifest["channels"] = {"bbar_0", "bbar_1", "bbar_2", "bbar_3"};
  manifest["layout"] = roughness_table_layout("sqrt(NdotV)", "RGBA");
  manifest["energy_compensation"] = {
      {"directional_albedo", "channel 0 (bbar_0) is E(NdotV, roughness)"},
      {"average_albedo", baked.average_albedo},
      {"average_albedo_rows", "E_avg at roughness = y / (size - 1)"},
      {"basis_hemispherical_averages", baked.basis_averages},
      {"average_fresnel", "F_avg = sum_i c_i * basis_hemispherical_averages[i] per channel"}};
  return manifest;
}

}  // namespace matc
