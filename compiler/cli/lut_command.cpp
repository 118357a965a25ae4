#include <fmt/core.h>

#include "commands.h"
#include "lut_options.h"
#include "matc/api/diagnostics.h"
#include "matc/options/option_names.h"
#include "matc/pipeline/batch.h"
#include "matc/pipeline/output_sink.h"
#include "matc/runtime/basis.h"

namespace matc::cli {
namespace {

struct LutCommandOptions {
  std::string output;
  std::optional<LutFormat> format;  // none: from the output's extension
  LutCliOptions lut;
};

int run_lut(const LutCommandOptions& options) {
  const std::filesystem::path output(options.output);
  std::optional<LutFormat> format = options.format;
  if (!format) {
    format = lut_format_from_extension(output.extension().string());
    if (!format) {
      fmt::print(stderr,
                 "matc lut: error: --format: cannot infer the format from '{}'; give --format "
                 "ktx2|dds|raw|header or an extension .ktx2, .dds, .bin or .h\n",
                 api::echoed(output.string(), 128));
      return kExitUsageError;
    }
  }
  const BakedLut baked = bake_lut(runtime::shipped_basis(options.lut.basis), options.lut.bake);
  try {
    DirectoryOutput directory(output.has_parent_path() ? output.parent_path() : ".");
    BatchCounts counts;
    for (const OutputFile& file :
         lut_output_files(baked, *format, options.lut.precision, output.filename().string()))
      counts.count(directory.write(file.name, file.bytes));
    fmt::print(stderr,
               "matc lut: {} ({}x{}, {} samples per texel, {}, {}): {} written, {} unchanged\n",
               output.string(), baked.lut.size, baked.lut.size, baked.lut.samples,
               lut_format_name(*format), lut_precision_name(options.lut.precision), counts.written,
               counts.unchanged);
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
  command
      ->add_option_function<std::string>(
          "--format",
          [options](const std::string& name) { options->format = option_value<LutFormat>(name); },
          "File format (default: from the extension)")
      ->check(CLI::IsMember(option_name_list<LutFormat>()));
  add_lut_options(*command, options->lut, "");

  return {command, [options] { return run_lut(*options); }};
}

}  // namespace matc::cli
