// `matc bake`: reflectivity and edge-tint maps (or n and k maps) into coefficient textures with
// mip chains computed in coefficient space (docs/baking.md).
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "batch_report.h"
#include "commands.h"
#include "matc/api/bake.h"
#include "name_options.h"
#include "option_help.h"
#include "progress_line.h"

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
  std::string format;
  std::string precision;
  std::string basis;
  bool f0 = false;
  bool error_map = false;
  bool keep_going = false;
  bool quiet = false;
  unsigned jobs = 0;  // threads; 0: one per hardware thread
  std::string depfile;
  bool write_depfile = false;
};

// The asset the map options describe, if any are given: the library checks it (at "matc bake",
// each map by its option) where the batch reaches it.
std::optional<api::BakeSource> command_line_asset(const BakeCommandOptions& options) {
  if (options.reflectivity.empty() && options.edge_tint.empty() && options.n.empty() &&
      options.k.empty())
    return std::nullopt;
  api::BakeDescription description;
  description.origin = "matc bake";
  description.reflectivity = {"--reflectivity", options.reflectivity};
  description.edge_tint = {"--edge-tint", options.edge_tint};
  description.n = {"--n", options.n};
  description.k = {"--k", options.k};
  description.name = options.name;
  description.name_label = "--name";
  description.linear = options.linear;
  return api::BakeSource::in_memory(std::move(description), "the command line");
}

int run_bake(const BakeCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<api::BakeSource> sources;
  for (const std::string& file : options.files)
    sources.push_back(api::BakeSource::file(file));
  if (std::optional<api::BakeSource> asset = command_line_asset(options))
    sources.push_back(std::move(*asset));
  if (sources.empty()) {
    fmt::print(stderr,
               "matc bake: error: nothing to bake; usage: matc bake --reflectivity FILE "
               "--edge-tint FILE [-o DIR], or matc bake ASSET.json... (see matc bake --help)\n");
    return kExitUsageError;
  }

  api::BakeOptions batch;
  batch.output_directory = options.output_directory;
  batch.basis = options.basis;
  batch.format = options.format;
  batch.precision = options.precision;
  batch.f0 = options.f0;
  batch.error_map = options.error_map;
  batch.jobs = options.jobs;
  batch.keep_going = options.keep_going;
  batch.depfile = depfile_path(options.depfile, options.write_depfile, options.output_directory,
                               kBakeDepfileName);
  batch.extra_dependencies = matc_binary_dependency();

  ProgressLine progress(!options.quiet && stderr_is_terminal());
  const api::BatchResult result = api::bake_batch(sources, batch, printed_events(progress));
  progress.clear();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_batch_summary({"matc bake", "baked"}, result, options.quiet, seconds);
  return result.failed > 0 ? kExitInputError : kExitSuccess;
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
  options->format = "ktx2";
  command->add_option("--format", options->format, "Texture file format")
      ->default_str(options->format)
      ->check(CLI::IsMember({"ktx2", "dds"}));
  add_name_option(*command, "--precision", options->precision, "lut_precision", "Texel precision",
                  "f16");
  add_name_option(*command, "--basis", options->basis, "basis", kBasisHelp);
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
