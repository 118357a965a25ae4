#include "pipeline/bake_batch.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/core.h>

#include "bake/bake_inputs.h"
#include "batch_reporter.h"
#include "pipeline/inputs_in_output_directory.h"
#include "pipeline/unique_names.h"

namespace matc {
namespace {

namespace fs = std::filesystem;

// As the compile warns about a material: texels whose curve the basis follows poorly, with the
// worst one named so an artist can find it.
void warn_if_poor_fit(const BakeAsset& asset, const BakeInputs& inputs,
                      const BakedCoefficients& baked, Diagnostics& diagnostics) {
  if (baked.poor_fit_texels == 0) return;
  const std::size_t texels = inputs.width * inputs.height;
  diagnostics.warning(
      !asset.source_path.empty() || !asset.first.is_file()
          ? asset.name_location
          : SourceLocation{asset.first.resolved.string(), 0, 0},
      asset.model == BakeModel::artistic ? "artistic" : "ior",
      fmt::format("poor fit in {} of {} texels ({:.1f}%): max |F - exact| = {:.3f} at texel ({}, "
                  "{}) (the measured metals stay under 0.02)",
                  baked.poor_fit_texels, texels,
                  100.0 * static_cast<double>(baked.poor_fit_texels) / static_cast<double>(texels),
                  baked.max_error, baked.worst_texel % inputs.width,
                  baked.worst_texel / inputs.width),
      asset.model == BakeModel::artistic
          ? "near-black texels (r near 0) and high reflectivity with a low edge tint (curves like "
            "a high-index dielectric's) are curves no 4-term basis follows; --error-map shows "
            "where"
          : "check the n, k values; curves this far from measured metals fit poorly; "
            "--error-map shows where");
}

struct Asset {
  std::optional<BakeAsset> asset;
  Diagnostics diagnostics;
  std::string label;
};

std::vector<Asset> read_assets(std::span<const BakeSource> sources) {
  std::vector<Asset> assets;
  for (const BakeSource& source : sources) {
    BakeAssetResult read =
        source.described ? *source.described : read_bake_asset_file(source.label);
    assets.push_back({std::move(read.asset), std::move(read.diagnostics), source.label});
  }
  return assets;
}

// Names unique within the batch, and no output that would overwrite an input.
void check_outputs(std::vector<Asset>& assets, const fs::path* directory) {
  std::optional<InputsInOutputDirectory> inputs;
  if (directory) {
    inputs.emplace(*directory);
    for (const Asset& entry : assets) {
      if (!entry.asset) continue;
      if (!entry.asset->source_path.empty())
        inputs->add(entry.asset->source_path, entry.asset->source_path);
      for (const MapInput* map : {&entry.asset->first, &entry.asset->second})
        if (map->is_file()) inputs->add(map->resolved, map->resolved.string());
    }
  }
  UniqueNames names;
  for (Asset& entry : assets) {
    if (!entry.asset) continue;
    const BakeAsset& asset = *entry.asset;
    if (!names.claim(asset.name, entry.label, asset.name_location, "a bake", entry.diagnostics))
      continue;
    if (!inputs) continue;
    std::vector<fs::path> outputs;
    for (const std::string& name : possible_bake_outputs(asset.name))
      outputs.push_back(*directory / name);
    if (const auto problem = inputs->overwrite_problem(outputs))
      entry.diagnostics.error(asset.name_location, "name", *problem, kOutputDirectoryRule);
  }
}

}  // namespace

BakeBatchResult bake_batch(std::span<const BakeSource> sources, OutputSink& output,
                           const BakeBatchOptions& options, const BatchEvents& events) {
  const fs::path* directory = output.directory();
  if (!options.depfile.empty() && !directory)
    throw std::invalid_argument("bake_batch: a depfile needs an output directory");
  const fs::path output_label = output_name(output);
  std::vector<Asset> assets = read_assets(sources);
  check_outputs(assets, directory);
  const bool inputs_valid = std::all_of(assets.begin(), assets.end(), [](const Asset& entry) {
    return !entry.diagnostics.has_errors();
  });
  BatchReporter reporter(events);

  BakeBatchResult result;
  BatchCounts& counts = result.counts;
  std::vector<fs::path> targets, dependencies;
  std::size_t finished = 0;
  bool stop = !inputs_valid && !options.keep_going;
  for (Asset& entry : assets) {
    if (entry.diagnostics.has_errors()) {
      ++counts.failed;
      reporter.diagnostics(entry.diagnostics);
      continue;
    }
    if (stop || options.cancel.stop_requested()) {
      ++counts.not_attempted;
      continue;
    }
    const BakeAsset& asset = *entry.asset;
    try {
      const std::optional<BakeInputs> inputs = load_bake_inputs(asset, entry.diagnostics);
      if (inputs) {
        const BakedCoefficients baked = bake_coefficients(*inputs, options.bake);
        warn_if_poor_fit(asset, *inputs, baked, entry.diagnostics);
        // Every byte exists before the first file is written: a failure leaves no partial set.
        const std::vector<OutputFile> files =
            baked_texture_files(asset, *inputs, baked, options.files);
        // All of the asset's textures or none (write_all writes large sets a file per thread).
        for (const WriteOutcome written : output.write_all(files))
          counts.count(written);
        for (const OutputFile& file : files)
          targets.push_back(output_label / file.name);
        if (!asset.source_path.empty()) dependencies.push_back(asset.source_path);
        for (const MapInput* map : {&asset.first, &asset.second})
          if (map->is_file()) dependencies.push_back(map->resolved);
      }
    } catch (const std::exception& error) {
      entry.diagnostics.error(asset.name_location, "", error.what(),
                              "a writable output directory (-o)");
    }
    reporter.progress({++finished, assets.size(), asset.name});
    reporter.diagnostics(entry.diagnostics);
    if (entry.diagnostics.has_errors()) {
      ++counts.failed;
      stop = !options.keep_going;
    } else {
      ++counts.done;
    }
  }
  result.cancelled = options.cancel.stop_requested();
  if (!options.depfile.empty() && counts.failed == 0 && !result.cancelled &&
      !write_batch_depfile(options.depfile, targets, std::move(dependencies),
                           options.extra_dependencies, reporter))
    ++counts.failed;
  return result;
}

}  // namespace matc
