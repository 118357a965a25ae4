#include <filesystem>
#include <optional>
#include <string>

#include <fmt/core.h>

#include "commands.h"
#include "lut_options.h"
#include "matc/api/diagnostics.h"
#include "matc/api/files.h"
#include "matc/api/options.h"
#include "matc/api/tables.h"

namespace matc::cli {
namespace {

struct LutCommandOptions {
  std::string output;
  std::string format;  // empty: from the output's extension
  LutCliOptions lut;
};

int run_lut(const LutCommandOptions& options) {
  const std::filesystem::path output(options.output);
  std::string format = options.format;
  if (format.empty()) {
    const std::optional<std::string> inferred =
        api::lut_format_of_extension(output.extension().string());
    if (!inferred) {
      fmt::print(stderr,
                 "matc lut: error: --format: cannot infer the format from '{}'; give --format "
                 "ktx2|dds|raw|header or an extension .ktx2, .dds, .bin or .h\n",
                 api::echoed(output.string(), 128));
      return kExitUsageError;
    }
    format = *inferred;
  }
  const api::PreintegratedTableOptions table{options.lut.basis, options.lut.size,
                                             options.lut.samples, options.lut.precision};
  try {
    const std::filesystem::path directory = output.has_parent_path() ? output.parent_path() : ".";
    std::filesystem::create_directories(directory);
    std::size_t written = 0, unchanged = 0;
    for (const api::OutputFile& file : api::lut_files(table, format, output.filename().string())) {
      ++(api::write_file((directory / file.name).string(), file.bytes) == api::WriteOutcome::written
             ? written
             : unchanged);
    }
    fmt::print(stderr,
               "matc lut: {} ({}x{}, {} samples per texel, {}, {}): {} written, {} unchanged\n",
               output.string(), table.size, table.size, table.samples, format, table.precision,
               written, unchanged);
  } catch (const std::exception& error) {
    fmt::print(stderr, "{}: error: {}\n", output.string(), error.what());
    return kExitInputError;
  }
  return kExitSuccess;
}

}  // namespace

Command register_lut(CLI::App& app) {
  auto options = std::make_shared<LutCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "lut", "Bake the preintegrated basis table (KTX2, DDS, raw or C++ header)");
  command
      ->add_option("-o,--output", options->output, "Output file; a .json manifest goes beside it")
      ->required();
  command->add_option("--format", options->format, "File format (default: from the extension)")
      ->check(CLI::IsMember(api::option_names("lut_format")));
  add_lut_options(*command, options->lut, "");

  return {command, [options] { return run_lut(*options); }};
}

}  // namespace matc::cli
