#include "bake/baked_texture_files.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <stb/stb_image_write.h>

#include "base/content_hash.h"
#include "base/json_format.h"
#include "formats/dds_writer.h"
#include "formats/ktx2_writer.h"
#include "matc/runtime/basis.h"
#include "matc/version.h"

namespace matc {
namespace {

using nlohmann::ordered_json;

std::string texture_file(LutFormat format, std::vector<float> CoefficientLevel::*plane,
                         const BakedCoefficients& baked, LutPrecision precision) {
  std::vector<formats::TexelImage> levels;
  for (const CoefficientLevel& level : baked.levels)
    levels.push_back({level.width, level.height, kCoefficientTextureChannels, level.*plane});
  return format == LutFormat::dds ? formats::encode_dds(levels, precision)
                                  : formats::encode_ktx2(levels, precision);
}

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

std::string error_map_png(const BakedCoefficients& baked) {
  const CoefficientLevel& base = baked.levels.front();
  std::vector<unsigned char> grey(base.width * base.height);
  for (std::size_t t = 0; t < grey.size(); ++t) {
    const double scaled = std::min(1.0, baked.error[t] / kErrorMapFullScale);
    grey[t] = static_cast<unsigned char>(std::lround(scaled * 255.0));
  }
  std::string png;
  stbi_write_png_to_func(append_bytes, &png, static_cast<int>(base.width),
                         static_cast<int>(base.height), 1, grey.data(),
                         static_cast<int>(base.width));
  return png;
}

ordered_json describe_input(const MapInput& map, const MapSamples& samples) {
  if (!map.is_file()) return {{"constant", *map.constant}};
  const ImageMap& image = *samples.image;
  return {{"file", map.resolved.generic_string()},
          {"xxh3", image.source_hash},
          {"format", image_file_format_name(image.format)},
          {"bits", image.bits},
          {"channels", image.file_channels},
          {"encoding", map_encoding_name(image.encoding)}};
}

}  // namespace

std::vector<std::string> possible_bake_outputs(std::string_view name) {
  std::vector<std::string> names;
  for (const char* plane : {"_c2", "_c3", "_f0"})
    for (LutFormat format : {LutFormat::ktx2, LutFormat::dds})
      names.push_back(fmt::format("{}{}{}", name, plane, lut_file_extension(format)));
  names.push_back(fmt::format("{}_error.png", name));
  names.push_back(fmt::format("{}_bake.json", name));
  return names;
}

std::vector<OutputFile> baked_texture_files(const BakeAsset& asset, const BakeInputs& inputs,
                                            const BakedCoefficients& baked,
                                            const BakeFileOptions& options) {
  const std::string_view extension = lut_file_extension(options.format);
  std::vector<OutputFile> files;
  ordered_json textures = ordered_json::object();
  const auto add_texture = [&](const char* key, std::vector<float> CoefficientLevel::*plane,
                               const char* holds) {
    OutputFile file{fmt::format("{}_{}{}", asset.name, key, extension),
                    texture_file(options.format, plane, baked, options.precision)};
    textures[key] = {{"file", file.name}, {"xxh3", hash_of_bytes(file.bytes)}, {"rgba", holds}};
    files.push_back(std::move(file));
  };
  add_texture("c2", &CoefficientLevel::c2, "c_2 of the red, green and blue curves; alpha 1");
  add_texture("c3", &CoefficientLevel::c3, "c_3 of the red, green and blue curves; alpha 1");
  if (!baked.levels.front().f0.empty()) {
    add_texture("f0", &CoefficientLevel::f0,
                "c_0 = F0 of red, green and blue (linear; mips are box averages); alpha 1");
  }

  const CoefficientLevel& base = baked.levels.front();
  const bool artistic = asset.model == BakeModel::artistic;
  ordered_json manifest;
  manifest["generator"] = fmt::format("matc {}", kVersion);
  manifest["name"] = asset.name;
  if (!asset.source_path.empty()) manifest["asset"] = asset.source_path;
  manifest["basis"] = runtime::basis_name(baked.basis);
  manifest["inputs"] = {
      {artistic ? "reflectivity" : "n", describe_input(asset.first, inputs.first)},
      {artistic ? "edge_tint" : "k", describe_input(asset.second, inputs.second)}};
  manifest["width"] = base.width;
  manifest["height"] = base.height;
  manifest["levels"] = baked.levels.size();
  manifest["format"] = lut_format_name(options.format);
  manifest["precision"] = lut_precision_name(options.precision);
  manifest["solve"] = bake_solve_name(baked.solve);
  if (baked.solve == BakeSolve::exact) manifest["solved_pairs"] = baked.solved_pairs;
  if (baked.solve == BakeSolve::exact || !baked.error.empty()) {
    manifest["max_error_level0"] = baked.max_error;
    manifest["poor_fit_texels"] = baked.poor_fit_texels;
  }
  manifest["textures"] = textures;
  manifest["reconstruction"] =
      "per colour channel: c0 = F0 (the F0 texture, or a base colour whose mips are box "
      "averages of linear F0), c1 = 1 - c0, c2 = C2, c3 = C3; sample every texture with the "
      "same trilinear sampler; matc_coefficients_from_baked(f0, c2, c3) in the shader library";
  if (!baked.error.empty()) {
    OutputFile file{fmt::format("{}_error.png", asset.name), error_map_png(baked)};
    manifest["error_map"] = {
        {"file", file.name},
        {"xxh3", hash_of_bytes(file.bytes)},
        {"meaning", fmt::format("level 0, per texel: the largest |F - exact| over cosines and "
                                "channels; grey 255 = {} or more, linear below",
                                kErrorMapFullScale)}};
    files.push_back(std::move(file));
  }
  files.push_back({fmt::format("{}_bake.json", asset.name), format_json(manifest)});
  return files;
}

}  // namespace matc
