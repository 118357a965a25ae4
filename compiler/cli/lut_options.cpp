#include "lut_options.h"

#include <vector>

#include "named_option.h"

namespace matc::cli {

void add_basis_option(CLI::App& app, runtime::BasisKind& basis) {
  add_named_option(
      app, "--basis", basis,
      "Fresnel basis: powers (default; the closed form m^6, mu m^3, mu m^9 with m = 1 - mu, "
      "near-minimax coefficients), extended (the authors' dielectrics extended with "
      "conductors, curves weighted by 1 - F0), paper (the authors' construction, "
      "coefficients matched at two angles) or f82 (exact for F82-tint and Schlick "
      "curves, for OpenPBR looks); docs/accuracy.md compares them");
}

void add_lut_options(CLI::App& app, LutCliOptions& options, const std::string& prefix) {
  app.add_option("--" + prefix + "size", options.bake.size, "LUT width and height in texels")
      ->capture_default_str()
      ->check(CLI::Range(kMinLutSize, kMaxLutSize));
  app.add_option("--" + prefix + "samples", options.bake.samples, "Hammersley samples per texel")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, kMaxLutSamples));
  add_named_option(app, "--" + prefix + "precision", options.precision, "Texel precision");
  add_basis_option(app, options.basis);
}

void add_coefficient_table_option(CLI::App& app, LutCliOptions& options) {
  add_named_option(app, "--coefficient-table-precision", options.coefficient_table_precision,
                   "Texel precision of the coefficient table DIR/matc_coefficient_table.<ext>");
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
