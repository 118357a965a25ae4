#include "lut/lut_files.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "base/json_format.h"
#include "formats/texel_bytes.h"
#include "formats/texture_file.h"
#include "header_writer.h"
#include "lut/energy.h"
#include "matc/version.h"

namespace matc {

namespace {

// A table's texels (`width` x `height` RGBA) in a texture format: KTX2, DDS or raw.
std::string encode_texture(std::size_t width, std::size_t height, std::span<const float> texels,
                           LutFormat format, LutPrecision precision) {
  return formats::encode_texture_file({width, height, runtime::kBasisSize, texels}, format,
                                      precision);
}

}  // namespace

Lut stored_as(Lut lut, LutPrecision precision) {
  if (precision == LutPrecision::f16) {
    for (float& value : lut.texels)
      value = formats::round_to_half(value);
  }
  return lut;
}

BakedLut bake_lut(const runtime::BasisView& basis, const LutOptions& options) {
  return std::move(bake_luts({&basis, 1}, options).front());
}

std::vector<BakedLut> bake_luts(std::span<const runtime::BasisView> bases,
                                const LutOptions& options) {
  std::vector<Lut> tables = preintegrate_luts(bases, options);
  std::vector<BakedLut> baked(bases.size());
  for (std::size_t b = 0; b < bases.size(); ++b) {
    baked[b].lut = std::move(tables[b]);
    baked[b].basis = bases[b].kind;
    baked[b].average_albedo = average_albedo(baked[b].lut);
    baked[b].basis_averages = basis_hemispherical_averages(bases[b]);
  }
  return baked;
}

std::vector<BakedLut> bake_luts(std::span<const runtime::BasisKind> bases,
                                const LutOptions& options) {
  std::vector<runtime::BasisView> views;
  for (const runtime::BasisKind basis : bases)
    views.push_back(runtime::shipped_basis(basis));
  return bake_luts(views, options);
}

std::string encode_lut(const BakedLut& baked, LutFormat format, LutPrecision precision) {
  if (format == LutFormat::header) return encode_lut_header(baked, precision);
  return encode_texture(baked.lut.size, baked.lut.size, baked.lut.texels, format, precision);
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

std::string encode_layered_lut(std::span<const BakedLut> layers, const LutAtlas& atlas,
                               LutFormat format, LutPrecision precision) {
  if (format == LutFormat::header) return encode_layered_lut_header(layers, atlas, precision);
  return encode_texture(atlas.width(), atlas.size, atlas.texels, format, precision);
}

nlohmann::ordered_json layered_lut_manifest(std::span<const BakedLut> layers, const LutAtlas& atlas,
                                            LutFormat format, LutPrecision precision) {
  nlohmann::ordered_json manifest = lut_manifest(layers.front(), format, precision);
  manifest["size"] = {atlas.width(), atlas.size};
  manifest["basis"] = "auto";
  manifest["layer_size"] = {atlas.size, atlas.size};
  manifest["layers"] = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < layers.size(); ++k) {
    manifest["layers"].push_back({{"basis", runtime::basis_name(layers[k].basis)},
                                  {"columns", {k * atlas.size, (k + 1) * atlas.size - 1}},
                                  {"basis_hemispherical_averages", layers[k].basis_averages}});
  }
  manifest["layout"]["layers"] =
      "each basis' table side by side, layer k in columns [k size, (k + 1) size); a material's "
      "<name>.json names its basis";
  manifest["layout"]["sampling"] =
      "linear filtering, clamp to edge, at (k size + u (size - 1) + 0.5) / (layers size) across "
      "for layer k and (roughness (size - 1) + 0.5) / size down";
  manifest["energy_compensation"]["basis_hemispherical_averages"] = "per layer (layers[k])";
  return manifest;
}

std::vector<OutputFile> lut_output_files(const BakedLut& baked, LutFormat format,
                                         LutPrecision precision, std::string_view file_name) {
  return {{std::string(file_name), encode_lut(baked, format, precision)},
          {fmt::format("{}.json", file_name), format_json(lut_manifest(baked, format, precision))}};
}

}  // namespace matc
