#include "matc/api/bake.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "batch_events.h"
#include "checked_options.h"
#include "matc/api/options.h"
#include "material/parse.h"
#include "optics/spectrum.h"
#include "pipeline/bake_batch.h"

namespace matc::api {
namespace {

namespace fs = std::filesystem;

// A map's value: constant values ("0.9,0.6,0.3", "0.5") or an image file.
bool looks_like_values(const std::string& text) {
  return !text.empty() && text.find_first_not_of("0123456789.,+-eE") == std::string::npos;
}

// The library's asset for a description, with what was found wrong in it (reported at its place
// in the batch).
matc::BakeSource described_source(const BakeDescription& description, const std::string& label) {
  BakeAssetResult result;
  const auto described = [&result, &label] {
    return matc::BakeSource::in_memory(std::move(result), label);
  };
  const SourceLocation origin{description.origin, 0, 0};
  const bool artistic =
      !description.reflectivity.value.empty() || !description.edge_tint.value.empty();
  const bool ior = !description.n.value.empty() || !description.k.value.empty();
  if (artistic && ior) {
    result.diagnostics.error(
        origin, "",
        fmt::format("{}/{} and {}/{} are given", description.reflectivity.label,
                    description.edge_tint.label, description.n.label, description.k.label),
        fmt::format("one pair: {} and {}, or {} and {}", description.reflectivity.label,
                    description.edge_tint.label, description.n.label, description.k.label));
    return described();
  }
  BakeAsset asset;
  asset.model = ior ? BakeModel::ior : BakeModel::artistic;
  const auto read = [&](const BakeMap& given, MapQuantity quantity, MapInput& map) {
    map.quantity = quantity;
    map.encoding = description.linear ? MapEncoding::linear : default_map_encoding(quantity);
    map.encoding_given = description.linear;
    if (given.value.empty()) {
      result.diagnostics.error(origin, "", fmt::format("{} is missing", given.label),
                               "an image file or constant values (R,G,B or one grey value)");
      return;
    }
    if (looks_like_values(given.value)) {
      const bool unit = quantity == MapQuantity::reflectivity || quantity == MapQuantity::edge_tint;
      try {
        const Rgb values =
            parse_channel_values(given.label, given.value, unit ? 1.0 : kMaxIorComponent);
        if (quantity == MapQuantity::n &&
            std::find(values.begin(), values.end(), 0.0) != values.end()) {
          result.diagnostics.error(
              origin, "", fmt::format("{}: n = 0 is not a material; give n > 0", given.label));
          return;
        }
        map.constant = values;
      } catch (const std::invalid_argument& error) {
        result.diagnostics.error(origin, "", error.what());
      }
      return;
    }
    map.file = given.value;
    map.resolved = fs::path(given.value).lexically_normal();
  };
  if (asset.model == BakeModel::artistic) {
    read(description.reflectivity, MapQuantity::reflectivity, asset.first);
    read(description.edge_tint, MapQuantity::edge_tint, asset.second);
  } else {
    read(description.n, MapQuantity::n, asset.first);
    read(description.k, MapQuantity::k, asset.second);
  }
  if (result.diagnostics.has_errors()) return described();
  asset.name = description.name;
  if (asset.name.empty()) {
    const MapInput& named = asset.first.is_file() ? asset.first : asset.second;
    asset.name = named.is_file() ? fs::path(named.file).stem().string() : std::string();
  }
  const std::string rule(kMaterialNameRule);
  if (asset.name.empty()) {
    result.diagnostics.error(origin, description.name_label, "is missing (both maps are constants)",
                             rule);
  } else if (auto problem = material_name_problem(asset.name)) {
    result.diagnostics.error(
        origin, description.name_label,
        fmt::format("{}{}", *problem,
                    description.name.empty() ? " (from the map's file name)" : ""),
        rule);
  }
  if (result.diagnostics.has_errors()) return described();
  asset.name_location = origin;
  result.asset = std::move(asset);
  return described();
}

}  // namespace

BatchResult bake_batch(std::span<const BakeSource> sources, const BakeOptions& options,
                       const BatchEvents& events, std::stop_token cancel) {
  if (options.output_directory.empty())
    throw std::invalid_argument("output_directory: empty; the folder the files go to");
  BakeBatchOptions batch;
  batch.bake.basis = basis_of({options.basis, {}, {}});
  batch.bake.f0 = options.f0;
  batch.bake.error_map = options.error_map;
  batch.bake.threads = options.jobs;
  batch.files.format = option_from_name("format", options.format, LutFormat::ktx2);
  if (batch.files.format != LutFormat::ktx2 && batch.files.format != LutFormat::dds) {
    throw std::invalid_argument(
        fmt::format("format: '{}' is not one of ktx2, dds", echoed(options.format)));
  }
  batch.files.precision = option_from_name("precision", options.precision, LutPrecision::f16);
  batch.keep_going = options.keep_going;
  batch.depfile = options.depfile;
  for (const std::string& dependency : options.extra_dependencies)
    batch.extra_dependencies.emplace_back(dependency);
  batch.cancel = std::move(cancel);

  std::vector<matc::BakeSource> inputs;
  inputs.reserve(sources.size());
  for (const BakeSource& source : sources) {
    inputs.push_back(source.described ? described_source(*source.described, source.path)
                                      : matc::BakeSource::file(source.path));
  }
  DirectoryOutput output(options.output_directory);
  const BakeBatchResult result = matc::bake_batch(inputs, output, batch, library_events(events));
  return public_result(result.counts, result.cancelled);
}

}  // namespace matc::api
