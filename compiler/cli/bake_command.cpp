// `matc bake`: reflectivity and edge-tint maps (or n and k maps) into coefficient textures with
// mip chains computed in coefficient space (docs/baking.md).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <future>
#include <optional>

#include <fmt/core.h>

#include "atomic_file.h"
#include "batch_report.h"
#include "channel_list.h"
#include "commands.h"
#include "lut_options.h"
#include "matc/bake/bake_inputs.h"
#include "matc/bake/baked_texture_files.h"
#include "matc/bake/coefficient_textures.h"
#include "matc/json_format.h"
#include "matc/material/parse.h"
#include "print_diagnostics.h"
#include "progress_line.h"
#include "unique_names.h"

namespace matc::cli {
namespace {

// `matc bake`: asset files, and/or one asset from the map options.
inline constexpr const char* kBakeDepfileName = "matc_bake.d";

struct BakeCommandOptions {
  std::vector<std::string> files;  // asset JSON files
  std::string reflectivity;        // a map file or constant values, for a command-line asset
  std::string edge_tint;
  std::string n;
  std::string k;
  std::string name;     // its name (default: the first map file's stem)
  bool linear = false;  // its 8- and 16-bit map files hold linear values, not sRGB
  std::string output_directory = "matc-bake";
  std::string format = "ktx2";
  std::string precision = "f16";
  std::string basis{runtime::basis_name(runtime::kDefaultBasis)};
  bool f0 = false;
  bool error_map = false;
  bool keep_going = false;
  bool quiet = false;
  unsigned jobs = 0;  // threads; 0: one per hardware thread
  std::string depfile;
  bool write_depfile = false;
};

namespace fs = std::filesystem;

// A map option's text: constant values ("0.9,0.6,0.3", "0.5") or an image file.
bool looks_like_values(const std::string& text) {
  return !text.empty() && text.find_first_not_of("0123456789.,+-eE") == std::string::npos;
}

struct Asset {
  std::optional<BakeAsset> asset;
  Diagnostics diagnostics;
  std::string label;  // what the summary calls it: the file, or "command line"
};

// The asset the map options describe, if any are given.
std::optional<Asset> command_line_asset(const BakeCommandOptions& options) {
  const bool artistic = !options.reflectivity.empty() || !options.edge_tint.empty();
  const bool ior = !options.n.empty() || !options.k.empty();
  if (!artistic && !ior) return std::nullopt;
  Asset result;
  result.label = "the command line";
  const SourceLocation command_line{"matc bake", 0, 0};
  if (artistic && ior) {
    result.diagnostics.error(command_line, "", "--reflectivity/--edge-tint and --n/--k are given",
                             "one pair: --reflectivity and --edge-tint, or --n and --k");
    return result;
  }
  BakeAsset asset;
  asset.model = artistic ? BakeModel::artistic : BakeModel::ior;
  const auto read = [&](const std::string& option, const std::string& text, MapQuantity quantity,
                        MapInput& map) {
    map.quantity = quantity;
    map.encoding = options.linear ? MapEncoding::linear : default_map_encoding(quantity);
    map.encoding_given = options.linear;
    if (text.empty()) {
      result.diagnostics.error(command_line, "", fmt::format("{} is missing", option),
                               "an image file or constant values (R,G,B or one grey value)");
      return;
    }
    if (looks_like_values(text)) {
      const bool unit = quantity == MapQuantity::reflectivity || quantity == MapQuantity::edge_tint;
      ChannelList values = parse_channel_list(option, text, unit ? 1.0 : kMaxIorComponent);
      if (values.values && quantity == MapQuantity::n &&
          std::find(values.values->begin(), values.values->end(), 0.0) != values.values->end())
        values = {std::nullopt, fmt::format("{}: n = 0 is not a material; give n > 0", option)};
      if (!values.values) {
        result.diagnostics.error(command_line, "", values.error);
        return;
      }
      map.constant = *values.values;
      return;
    }
    map.file = text;
    map.resolved = fs::path(text).lexically_normal();
  };
  if (artistic) {
    read("--reflectivity", options.reflectivity, MapQuantity::reflectivity, asset.first);
    read("--edge-tint", options.edge_tint, MapQuantity::edge_tint, asset.second);
  } else {
    read("--n", options.n, MapQuantity::n, asset.first);
    read("--k", options.k, MapQuantity::k, asset.second);
  }
  if (result.diagnostics.has_errors()) return result;
  asset.name = options.name;
  if (asset.name.empty()) {
    const MapInput& named = asset.first.is_file() ? asset.first : asset.second;
    asset.name = named.is_file() ? fs::path(named.file).stem().string() : std::string();
  }
  const std::string rule(kMaterialNameRule);
  if (asset.name.empty()) {
    result.diagnostics.error(command_line, "--name", "is missing (both maps are constants)", rule);
  } else if (auto problem = material_name_problem(asset.name)) {
    result.diagnostics.error(
        command_line, "--name",
        fmt::format("{}{}", *problem, options.name.empty() ? " (from the map's file name)" : ""),
        rule);
  }
  if (result.diagnostics.has_errors()) return result;
  asset.name_location = command_line;
  result.asset = std::move(asset);
  return result;
}

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

std::vector<Asset> read_assets(const BakeCommandOptions& options) {
  std::vector<Asset> assets;
  for (const std::string& file : options.files) {
    BakeAssetResult parsed = read_bake_asset_file(file);
    assets.push_back({std::move(parsed.asset), std::move(parsed.diagnostics), file});
  }
  if (auto asset = command_line_asset(options)) assets.push_back(std::move(*asset));
  return assets;
}

// Names unique within the run, and no output that would overwrite an input.
void check_outputs(std::vector<Asset>& assets, const fs::path& output_directory) {
  InputsInOutputDirectory inputs(output_directory);
  for (const Asset& entry : assets) {
    if (!entry.asset) continue;
    if (!entry.asset->source_path.empty())
      inputs.add(entry.asset->source_path, entry.asset->source_path);
    for (const MapInput* map : {&entry.asset->first, &entry.asset->second})
      if (map->is_file()) inputs.add(map->resolved, map->resolved.string());
  }
  UniqueNames names;
  for (Asset& entry : assets) {
    if (!entry.asset) continue;
    const BakeAsset& asset = *entry.asset;
    if (!names.claim(asset.name, entry.label, asset.name_location, "a bake", entry.diagnostics))
      continue;
    std::vector<fs::path> outputs;
    for (const std::string& name : possible_bake_outputs(asset.name))
      outputs.push_back(output_directory / name);
    if (const auto problem = inputs.overwrite_problem(outputs))
      entry.diagnostics.error(asset.name_location, "name", *problem, kOutputDirectoryRule);
  }
}

int run_bake(const BakeCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path output_directory(options.output_directory);
  std::vector<Asset> assets = read_assets(options);
  if (assets.empty()) {
    fmt::print(stderr,
               "matc bake: error: nothing to bake; usage: matc bake --reflectivity FILE "
               "--edge-tint FILE [-o DIR], or matc bake ASSET.json... (see matc bake --help)\n");
    return kExitUsageError;
  }
  check_outputs(assets, output_directory);
  const bool inputs_valid = std::all_of(assets.begin(), assets.end(), [](const Asset& entry) {
    return !entry.diagnostics.has_errors();
  });

  BakeOptions bake_options;
  bake_options.basis = basis_of(options.basis);
  bake_options.f0 = options.f0;
  bake_options.error_map = options.error_map;
  bake_options.threads = options.jobs;
  BakeFileOptions file_options;
  file_options.format = *lut_format_from_name(options.format);
  file_options.precision = *lut_precision_from_name(options.precision);

  BatchCounts counts;
  std::vector<fs::path> targets, dependencies;
  ProgressLine progress(assets.size(), !options.quiet && stderr_is_terminal());
  bool stop = !inputs_valid && !options.keep_going;
  for (Asset& entry : assets) {
    if (entry.diagnostics.has_errors()) {
      ++counts.failed;
      print_diagnostics(entry.diagnostics);
      continue;
    }
    if (stop) {
      ++counts.not_attempted;
      continue;
    }
    const BakeAsset& asset = *entry.asset;
    try {
      const std::optional<BakeInputs> inputs = load_bake_inputs(asset, entry.diagnostics);
      if (inputs) {
        const BakedCoefficients baked = bake_coefficients(*inputs, bake_options);
        warn_if_poor_fit(asset, *inputs, baked, entry.diagnostics);
        // Every byte exists before the first file is written: a failure leaves no partial set.
        const std::vector<OutputFile> files =
            baked_texture_files(asset, *inputs, baked, file_options);
        fs::create_directories(output_directory);
        // The textures run to hundreds of MB: written at once, each atomically (copying into
        // the page cache is most of a write's time, and it runs on the writing thread).
        std::vector<std::future<WriteOutcome>> writes;
        for (const OutputFile& file : files) {
          writes.push_back(std::async(std::launch::async, [&output_directory, &file] {
            return write_file_atomically(output_directory / file.name, file.bytes);
          }));
        }
        for (std::size_t i = 0; i < files.size(); ++i) {
          counts.count(writes[i].get());
          targets.push_back(output_directory / files[i].name);
        }
        if (!asset.source_path.empty()) dependencies.push_back(asset.source_path);
        for (const MapInput* map : {&asset.first, &asset.second})
          if (map->is_file()) dependencies.push_back(map->resolved);
      }
    } catch (const std::exception& error) {
      entry.diagnostics.error(asset.name_location, "", error.what(),
                              "a writable output directory (-o)");
    }
    progress.finished(asset.name);
    print_diagnostics(entry.diagnostics);
    if (entry.diagnostics.has_errors()) {
      ++counts.failed;
      stop = !options.keep_going;
    } else {
      ++counts.done;
    }
  }
  progress.clear();

  const fs::path depfile =
      depfile_path(options.depfile, options.write_depfile, output_directory, kBakeDepfileName);
  if (!depfile.empty() && counts.failed == 0 && !write_depfile(depfile, targets, dependencies))
    ++counts.failed;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_batch_summary({"matc bake", "baked"}, counts, options.quiet, seconds);
  return counts.failed > 0 ? kExitInputError : kExitSuccess;
}

}  // namespace

Command register_bake(CLI::App& app) {
  auto options = std::make_shared<BakeCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "bake",
      "Bake reflectivity and edge-tint maps (or n and k maps) into coefficient textures with mip "
      "chains computed in coefficient space (KTX2 or DDS)");
  command->add_option("files", options->files, "Bake asset files (.json: docs/baking.md)");
  command->add_option("--reflectivity", options->reflectivity,
                      "Reflectivity map (PNG, JPEG, OpenEXR) or constant R,G,B / grey");
  command->add_option("--edge-tint", options->edge_tint,
                      "Edge-tint map or constant, with --reflectivity");
  command->add_option("--n", options->n, "Refractive index map (OpenEXR) or constant, with --k");
  command->add_option("--k", options->k, "Extinction coefficient map or constant, with --n");
  command->add_option("--name", options->name,
                      "Name of the command-line asset's files (default: the first map's "
                      "file name without extension)");
  command->add_flag("--linear", options->linear,
                    "The command-line maps hold linear values (default: PNG and JPEG "
                    "reflectivity and edge tint are sRGB-encoded; n, k are linear)");
  command->add_option("-o,--output", options->output_directory, "Output directory")
      ->capture_default_str();
  command->add_option("--format", options->format, "Texture file format")
      ->capture_default_str()
      ->check(CLI::IsMember({"ktx2", "dds"}));
  command->add_option("--precision", options->precision, "Texel precision")
      ->capture_default_str()
      ->check(CLI::IsMember({"f16", "f32"}));
  add_basis_option(*command, options->basis);
  command->add_flag("--f0", options->f0,
                    "Also write NAME_f0 (linear F0 with coefficient-space mips), for "
                    "engines whose base-colour mips are not box averages of linear F0");
  command->add_flag("--error-map", options->error_map,
                    "Also write NAME_error.png: level 0's largest |F - exact| per texel "
                    "(255 = 0.01 or more)");
  add_keep_going_and_quiet(*command, options->keep_going, options->quiet,
                           "Bake the remaining assets after one fails",
                           "progress and summary lines");
  command->add_option("-j,--jobs", options->jobs, "Threads (default: one per hardware thread)")
      ->check(CLI::Range(1u, 1024u));
  add_depfile_options(*command, options->depfile, options->write_depfile,
                      "asset files, maps, the matc binary", kBakeDepfileName);

  return {command, [options] { return run_bake(*options); }, true};
}

}  // namespace matc::cli
