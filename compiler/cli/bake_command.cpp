// `matc bake`: reflectivity and edge-tint maps (or n and k maps) into coefficient textures with
// mip chains computed in coefficient space (docs/baking.md).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/core.h>

#include "batch_report.h"
#include "channel_list.h"
#include "commands.h"
#include "lut_options.h"
#include "matc/api/diagnostics.h"
#include "matc/material/parse.h"
#include "matc/pipeline/bake_batch.h"
#include "named_option.h"
#include "print_diagnostics.h"
#include "progress_line.h"

namespace matc::cli {
namespace {

// `matc bake`: asset files, and/or one asset from the map options.
inline constexpr const char* kBakeDepfileName = "matc_bake.d";
// The containers that hold mip chains.
inline constexpr std::array<LutFormat, 2> kTextureFormats = {LutFormat::ktx2, LutFormat::dds};

struct BakeCommandOptions {
  std::vector<std::string> files;  // asset JSON files
  std::string reflectivity;        // a map file or constant values, for a command-line asset
  std::string edge_tint;
  std::string n;
  std::string k;
  std::string name;     // its name (default: the first map file's stem)
  bool linear = false;  // its 8- and 16-bit map files hold linear values, not sRGB
  std::string output_directory = "matc-bake";
  LutFormat format = LutFormat::ktx2;
  LutPrecision precision = LutPrecision::f16;
  runtime::BasisKind basis = runtime::kDefaultBasis;
  bool f0 = false;
  bool error_map = false;
  bool keep_going = false;
  bool quiet = false;
  unsigned jobs = 0;  // threads; 0: one per hardware thread
  std::string depfile;
  bool write_depfile = false;
};

namespace fs = std::filesystem;

// The bake batch's events printed as the other batches' are (printed_events): the bake is not on
// the public API yet, so its events carry the library's own diagnostics.
BatchEvents printed_bake_events(ProgressLine& progress) {
  BatchEvents events;
  events.diagnostics = [&progress](const Diagnostics& diagnostics) {
    progress.print_above([&] { print_diagnostics(diagnostics); });
  };
  events.progress = [&progress](const BatchProgress& done) {
    progress.update(done.done, done.total, done.name);
  };
  events.error = [&progress](const std::string& where, const std::string& message) {
    progress.print_above([&] {
      fmt::print(stderr, "{}: error: {}\n", api::printable(where), api::printable(message));
    });
  };
  return events;
}

// A map option's text: constant values ("0.9,0.6,0.3", "0.5") or an image file.
bool looks_like_values(const std::string& text) {
  return !text.empty() && text.find_first_not_of("0123456789.,+-eE") == std::string::npos;
}

// The asset the map options describe, if any are given.
std::optional<BakeSource> command_line_asset(const BakeCommandOptions& options) {
  const bool artistic = !options.reflectivity.empty() || !options.edge_tint.empty();
  const bool ior = !options.n.empty() || !options.k.empty();
  if (!artistic && !ior) return std::nullopt;
  BakeAssetResult result;
  // The asset as the batch takes it, with what was found wrong in the options so far.
  const auto described = [&result] {
    return BakeSource::in_memory(std::move(result), "the command line");
  };
  const SourceLocation command_line{"matc bake", 0, 0};
  if (artistic && ior) {
    result.diagnostics.error(command_line, "", "--reflectivity/--edge-tint and --n/--k are given",
                             "one pair: --reflectivity and --edge-tint, or --n and --k");
    return described();
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
  if (result.diagnostics.has_errors()) return described();
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
  if (result.diagnostics.has_errors()) return described();
  asset.name_location = command_line;
  result.asset = std::move(asset);
  return described();
}

int run_bake(const BakeCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path output_directory(options.output_directory);
  std::vector<BakeSource> sources;
  for (const std::string& file : options.files)
    sources.push_back(BakeSource::file(file));
  if (std::optional<BakeSource> asset = command_line_asset(options))
    sources.push_back(std::move(*asset));
  if (sources.empty()) {
    fmt::print(stderr,
               "matc bake: error: nothing to bake; usage: matc bake --reflectivity FILE "
               "--edge-tint FILE [-o DIR], or matc bake ASSET.json... (see matc bake --help)\n");
    return kExitUsageError;
  }

  BakeBatchOptions batch;
  batch.bake.basis = options.basis;
  batch.bake.f0 = options.f0;
  batch.bake.error_map = options.error_map;
  batch.bake.threads = options.jobs;
  batch.files.format = options.format;
  batch.files.precision = options.precision;
  batch.keep_going = options.keep_going;
  batch.depfile =
      depfile_path(options.depfile, options.write_depfile, output_directory, kBakeDepfileName);
  batch.extra_dependencies = matc_binary_dependency();

  DirectoryOutput output(output_directory);
  ProgressLine progress(!options.quiet && stderr_is_terminal());
  const BakeBatchResult result = bake_batch(sources, output, batch, printed_bake_events(progress));
  progress.clear();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  api::BatchResult counts;
  counts.compiled = result.counts.done;
  counts.written = result.counts.written;
  counts.unchanged = result.counts.unchanged;
  counts.failed = result.counts.failed;
  counts.not_attempted = result.counts.not_attempted;
  print_batch_summary({"matc bake", "baked"}, counts, options.quiet, seconds);
  return result.counts.failed > 0 ? kExitInputError : kExitSuccess;
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
  add_named_option(*command, "--format", options->format, "Texture file format",
                   std::span<const LutFormat>(kTextureFormats));
  add_named_option(*command, "--precision", options->precision, "Texel precision");
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
