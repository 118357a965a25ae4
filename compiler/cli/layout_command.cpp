// `matc layout`: the files a run writes, for build systems that declare outputs before running
// matc, and the generator of the CMake function's and Bazel rule's lists of them.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "commands.h"
#include "emit_option.h"
#include "generated_source.h"
#include "matc/api/diagnostics.h"
#include "matc/emit/output_layout.h"
#include "matc/material/parse.h"
#include "named_option.h"

namespace matc::cli {
namespace {

struct LayoutOptions {
  std::vector<std::string> names;  // material names (their JSON "name")
  std::vector<std::string> emit;   // empty: every kind
  LutFormat lut_format = LutFormat::ktx2;
  bool no_shared = false;
  bool shared_only = false;
  std::string generate;  // "cmake" or "bazel": the build systems' lists as source
  std::string output;    // where --generate writes (default: standard output)
};

int run_layout(const LayoutOptions& options) {
  if (!options.generate.empty()) {
    return write_generated_source(options.output, options.generate == "cmake"
                                                      ? output_layout_cmake_source()
                                                      : output_layout_bazel_source());
  }
  for (const std::string& name : options.names) {
    if (const auto problem = material_name_problem(name)) {
      fmt::print(stderr, "matc layout: error: '{}': {}; {}\n", api::echoed(name), *problem,
                 kMaterialNameRule);
      return kExitUsageError;
    }
  }
  std::set<OutputKind> emit;
  for (const std::string& name : options.emit)
    emit.insert(*option_value<OutputKind>(name));
  if (emit.empty()) emit = all_output_kinds();
  std::vector<std::string> files;
  if (!options.no_shared) files = shared_file_names(emit, options.lut_format);
  for (const std::string& name : options.names)
    for (std::string& file : material_file_names(emit, name))
      files.push_back(std::move(file));
  // As the compile: only a batch writes the manifest.
  if (!options.no_shared && !options.shared_only && emit.contains(OutputKind::json))
    files.emplace_back(manifest_file_name());
  for (const std::string& file : files)
    fmt::print("{}\n", file);
  return kExitSuccess;
}

}  // namespace

Command register_layout(CLI::App& app) {
  auto options = std::make_shared<LayoutOptions>();
  CLI::App* command = app.add_subcommand(
      "layout",
      "Print the names of the files a compile writes (one per line) for these options and "
      "material names, or the CMake and Bazel lists of them");
  command->add_option("names", options->names, "Material names (a material file's \"name\")");
  add_emit_option(*command, options->emit, "Output kinds, as the compile's --emit (default: all)");
  add_named_option(*command, "--lut", options->lut_format,
                   "The tables' file format, as the compile's");
  CLI::Option* no_shared =
      command->add_flag("--no-shared", options->no_shared, "Only the materials' own files");
  command->add_flag("--shared-only", options->shared_only, "Only the shared files")
      ->excludes(no_shared);
  CLI::Option* generate =
      command
          ->add_option("--generate", options->generate,
                       "Write the layout as the CMake function's (cmake/MatcOutputLayout.cmake) "
                       "or the Bazel rule's (bazel/matc_layout.bzl) source instead")
          ->check(CLI::IsMember({"cmake", "bazel"}));
  command->add_option("-o,--output", options->output, "Where --generate writes (default: stdout)")
      ->needs(generate);
  return {command, [options] { return run_layout(*options); }};
}

}  // namespace matc::cli
