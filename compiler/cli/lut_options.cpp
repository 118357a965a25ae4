#include "lut_options.h"

#include "name_options.h"
#include "option_help.h"

namespace matc::cli {

void add_lut_options(CLI::App& app, LutCliOptions& options, const std::string& prefix,
                     bool per_material_basis) {
  app.add_option("--" + prefix + "size", options.size, kLutSizeHelp)
      ->capture_default_str()
      ->check(CLI::Range(api::kMinLutSize, api::kMaxLutSize));
  app.add_option("--" + prefix + "samples", options.samples, kLutSamplesHelp)
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, api::kMaxLutSamples));
  add_name_option(app, "--" + prefix + "precision", options.precision, "lut_precision",
                  kLutPrecisionHelp);
  if (per_material_basis) {
    add_name_option(app, "--basis", options.basis, "build_basis", kBuildBasisHelp,
                    api::option_default("build_basis"));
  } else {
    add_name_option(app, "--basis", options.basis, "basis", kBasisHelp);
  }
}

void add_coefficient_table_option(CLI::App& app, LutCliOptions& options) {
  add_name_option(app, "--coefficient-table-precision", options.coefficient_table_precision,
                  "lut_precision", kCoefficientTablePrecisionHelp, "f16");
}

api::BuildOptions table_build_options(const LutCliOptions& lut, bool embed_lut,
                                      std::size_t embed_lut_size) {
  api::BuildOptions build;
  build.lut_size = lut.size;
  build.lut_samples = lut.samples;
  build.lut_precision = lut.precision;
  build.coefficient_table_precision = lut.coefficient_table_precision;
  build.embed_lut = embed_lut ? embed_lut_size : 0;
  build.compile.basis = lut.basis;
  return build;
}

}  // namespace matc::cli
