#include <fmt/core.h>

#include "commands.h"
#include "lut_options.h"
#include "matc/runtime/basis.h"

namespace matc::cli {

int run_lut(const LutCommandOptions& options) {
  const std::filesystem::path output(options.output);
  std::optional<LutFormat> format = lut_format_from_name(options.format);
  if (options.format.empty()) {
    format = lut_format_from_extension(output.extension().string());
    if (!format) {
      fmt::print(stderr,
                 "matc lut: error: --format: cannot infer the format from '{}'; give --format "
                 "ktx2|dds|raw|header or an extension .ktx2, .dds, .bin or .h\n",
                 output.string());
      return kExitUsageError;
    }
  }
  const BakedLut baked =
      bake_lut(runtime::shipped_basis(basis_of(options.lut.basis)), options.lut.bake);
  try {
    const LutWriteCounts counts =
        write_lut_files(output, baked, *format, precision_of(options.lut));
    fmt::print(stderr,
               "matc lut: {} ({}x{}, {} samples per texel, {}, {}): {} written, {} unchanged\n",
               output.string(), baked.lut.size, baked.lut.size, baked.lut.samples,
               lut_format_name(*format), options.lut.precision, counts.written, counts.unchanged);
  } catch (const std::exception& error) {
    fmt::print(stderr, "{}: error: {}\n", output.string(), error.what());
    return kExitInputError;
  }
  return kExitSuccess;
}

}  // namespace matc::cli
