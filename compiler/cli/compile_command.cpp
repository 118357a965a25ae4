#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <fmt/format.h>

#include "batch_report.h"
#include "commands.h"
#include "device_validation_report.h"
#include "emit_option.h"
#include "file_list.h"
#include "lut_options.h"
#include "matc/api/batch.h"
#include "matc/api/diagnostics.h"
#include "matc/api/options.h"
#include "name_options.h"
#include "progress_line.h"

namespace matc::cli {
namespace {

struct CompileOptions {
  std::vector<std::string> files;
  std::string files_from;  // --files-from: a file listing more, one per line
  std::string output_directory = "matc-out";
  bool keep_going = false;
  bool quiet = false;
  unsigned jobs = 0;              // -j: materials compiled at once; 0: one per hardware thread
  std::string depfile;            // --depfile FILE: Make-syntax dependencies of every output
  bool write_depfile = false;     // -MD: the same, as <output directory>/matc.d
  std::vector<std::string> emit;  // empty: every kind
  bool no_shared = false;         // --no-shared: only each material's own files
  bool shared_only = false;       // --shared-only: only the shared files (no material given)
  std::string lut_format;
  LutCliOptions lut;
  bool embed_lut = false;
  std::size_t embed_lut_size = 32;
  bool validate = false;  // run each material's shaders on a device before writing its files
  api::DeviceOptions device;
  api::CompileOptions color;  // its colour space and gamut mapping (the basis is lut's)
};

inline constexpr const char* kDepfileName = "matc.d";

api::BuildOptions build_options(const CompileOptions& options) {
  api::BuildOptions build =
      table_build_options(options.lut, options.embed_lut, options.embed_lut_size);
  build.emit = options.emit;
  build.lut_format = options.lut_format;
  build.compile.color_space = options.color.color_space;
  build.compile.gamut_mapping = options.color.gamut_mapping;
  return build;
}

int run_compile(const CompileOptions& options) {
  const api::Build build(build_options(options));
  std::unique_ptr<api::DeviceValidation> validation;
  api::BatchOptions batch;
  if (options.validate) {
    validation = open_device_validation(build, options.device);
    if (!validation) return kExitNoDevice;
    std::vector<std::string> failed_checks;
    if (!validate_shared_files_and_report(*validation, &failed_checks)) {
      fmt::print(stderr,
                 "matc: error: {} differ from the CPU runtime on the Vulkan device (lines "
                 "above); nothing written\n",
                 fmt::join(failed_checks, " and "));
      return kExitValidationFailed;
    }
    batch.check_material = [&validation](const api::CompiledMaterial& compiled) {
      return validate_and_report(*validation, compiled);
    };
  }
  batch.jobs = options.jobs;
  batch.keep_going = options.keep_going;
  batch.no_shared = options.no_shared;
  batch.shared_only = options.shared_only;
  batch.output_directory = options.output_directory;
  batch.depfile =
      depfile_path(options.depfile, options.write_depfile, options.output_directory, kDepfileName);
  batch.extra_dependencies = matc_binary_dependency();

  std::vector<api::BatchSource> sources;
  sources.reserve(options.files.size());
  for (const std::string& file : options.files)
    sources.push_back(api::BatchSource::file(file));
  ProgressLine progress(!options.quiet && stderr_is_terminal());
  const api::BatchResult result =
      api::compile_batch(build, sources, batch, printed_events(progress));
  progress.clear();
  print_batch_summary({"matc", "compiled"}, result, options.quiet);
  if (result.failed_checks > 0) return kExitValidationFailed;
  return result.failed > 0 ? kExitInputError : kExitSuccess;
}

// The command line's checks that need every file: then the batch.
int run_compile_command(CompileOptions options) {
  if (!options.files_from.empty()) {
    const FileList listed = read_file_list(options.files_from);
    if (!listed.error.empty()) {
      fmt::print(stderr, "{}: error: --files-from: {}\n", api::printable(options.files_from),
                 listed.error);
      return kExitUsageError;
    }
    options.files.insert(options.files.end(), listed.paths.begin(), listed.paths.end());
  }
  if (options.shared_only && !options.files.empty()) {
    fmt::print(stderr,
               "matc: error: --shared-only writes no material's files; give no material file "
               "(compile materials with --no-shared in their own runs)\n");
    return kExitUsageError;
  }
  if (options.files.empty() && !options.shared_only) {
    fmt::print(stderr,
               "matc: error: no material files given; usage: matc [-o DIR] FILES... "
               "(see matc --help)\n");
    return kExitUsageError;
  }
  return run_compile(options);
}

}  // namespace

Command register_compile(CLI::App& app) {
  auto options = std::make_shared<CompileOptions>();
  app.add_option("files", options->files,
                 "Material files (.json) and MaterialX documents (.mtlx) to compile");
  app.add_option("--files-from", options->files_from,
                 "Also compile the files listed in FILE, one path per line (- for standard input): "
                 "for lists longer than a command line holds");
  app.add_option("-o,--output", options->output_directory, "Output directory (created if missing)")
      ->capture_default_str();
  add_keep_going_and_quiet(app, options->keep_going, options->quiet,
                           "Compile the remaining files after one fails",
                           "progress and summary lines");
  app.add_option("-j,--jobs", options->jobs,
                 "Materials compiled at once (default: one per hardware thread)")
      ->check(CLI::Range(1u, 1024u));
  add_depfile_options(app, options->depfile, options->write_depfile,
                      "inputs, spectral files, the matc binary", kDepfileName);
  add_emit_option(app, options->emit,
                  "Outputs to write, comma-separated (default: all): shader snippets, SPIR-V, "
                  "C headers, JSON manifests, the LUT, the coefficient table of textured metals, "
                  "the LTC table of area lights");
  CLI::Option* no_shared_option = app.add_flag(
      "--no-shared", options->no_shared,
      "Write only each material's own files (<name>.*), not the shared library, tables and "
      "manifest: one build action per material (docs/scaling.md)");
  app.add_flag("--shared-only", options->shared_only,
               "Write only the shared files (matc_fresnel.*, the tables), from no material file: "
               "the one shared action beside per-material --no-shared actions")
      ->excludes(no_shared_option);
  add_name_option(app, "--lut", options->lut_format, "lut_format",
                  "File format of the tables DIR/matc_lut.<ext>, DIR/matc_coefficient_table.<ext> "
                  "and DIR/matc_ltc.<ext>");
  app.add_flag("--embed-lut", options->embed_lut,
               "Also embed a small table in matc_fresnel.glsl/.hlsl as a constant array");
  app.add_option("--embed-lut-size", options->embed_lut_size, "Width and height of that table")
      ->capture_default_str()
      ->check(CLI::Range(api::kMinLutSize, api::kMaxEmbeddedLutSize));
  add_lut_options(app, options->lut, "lut-", true);
  add_color_name_options(app, options->color);
  add_coefficient_table_option(app, options->lut);
  app.add_flag("--validate", options->validate,
               "Run each material's GLSL and HLSL shaders on a Vulkan device (lavapipe) against "
               "the CPU runtime before writing its files");
  add_device_options(app, options->device);
  return {&app, [options] { return run_compile_command(*options); }, true};
}

}  // namespace matc::cli
