#include "lut_options.h"

#include <vector>

#include "named_option.h"
#include "option_help.h"

namespace matc::cli {

void add_basis_option(CLI::App& app, runtime::BasisKind& basis) {
  add_named_option(app, "--basis", basis, kBasisHelp);
}

void add_lut_options(CLI::App& app, LutCliOptions& options, const std::string& prefix) {
  app.add_option("--" + prefix + "size", options.bake.size, kLutSizeHelp)
      ->capture_default_str()
      ->check(CLI::Range(kMinLutSize, kMaxLutSize));
  app.add_option("--" + prefix + "samples", options.bake.samples, kLutSamplesHelp)
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, kMaxLutSamples));
  add_named_option(app, "--" + prefix + "precision", options.precision, kLutPrecisionHelp);
  add_basis_option(app, options.basis);
}

void add_coefficient_table_option(CLI::App& app, LutCliOptions& options) {
  add_named_option(app, "--coefficient-table-precision", options.coefficient_table_precision,
                   kCoefficientTablePrecisionHelp);
}

BuildOptions table_build_options(const LutCliOptions& lut, bool embed_lut,
                                 std::size_t embed_lut_size) {
  BuildOptions build;
  build.lut = lut.bake;
  build.lut_precision = lut.precision;
  build.coefficient_table_precision = lut.coefficient_table_precision;
  build.embedded_lut_size = embed_lut ? embed_lut_size : 0;
  build.basis = lut.basis;
  return build;
}

}  // namespace matc::cli
