// `matc layout`: the files a run writes, for build systems that declare outputs before running
// matc, and the generator of the CMake function's and Bazel rule's lists of them.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "commands.h"
#include "emit_option.h"
#include "generated_source.h"
#include "matc/api/layout.h"
#include "name_options.h"

namespace matc::cli {
namespace {

struct LayoutOptions {
  std::vector<std::string> names;  // material names (their JSON "name")
  api::LayoutOptions layout;
  std::string generate;  // "cmake" or "bazel": the build systems' lists as source
  std::string output;    // where --generate writes (default: standard output)
};

int run_layout(const LayoutOptions& options) {
  if (!options.generate.empty())
    return write_generated_source(options.output, api::output_layout_source(options.generate));
  std::vector<std::string> files;
  try {
    files = api::output_file_names(options.names, options.layout);
  } catch (const std::invalid_argument& error) {
    fmt::print(stderr, "matc layout: error: {}\n", error.what());
    return kExitUsageError;
  }
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
  add_emit_option(*command, options->layout.emit,
                  "Output kinds, as the compile's --emit (default: all)");
  add_name_option(*command, "--lut", options->layout.lut_format, "lut_format",
                  "The tables' file format, as the compile's");
  CLI::Option* no_shared =
      command->add_flag("--no-shared", options->layout.no_shared, "Only the materials' own files");
  command->add_flag("--shared-only", options->layout.shared_only, "Only the shared files")
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
