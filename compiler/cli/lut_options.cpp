#include "lut_options.h"

#include <vector>

#include "matc/json_format.h"
#include "matc/pipeline/atomic_file.h"

namespace matc::cli {

void add_basis_option(CLI::App& app, std::string& basis) {
  std::vector<std::string> names;
  for (const runtime::BasisKind kind : runtime::kShippedBases)
    names.emplace_back(runtime::basis_name(kind));
  app.add_option("--basis", basis,
                 "Fresnel basis: extended (default; the authors' dielectrics extended with "
                 "conductors, curves weighted by 1 - F0, near-minimax coefficients), paper (the "
                 "authors' construction, coefficients matched at two angles) or f82 (exact for "
                 "F82-tint and Schlick curves, for OpenPBR looks); docs/accuracy.md compares them")
      ->capture_default_str()
      ->check(CLI::IsMember(names));
}

void add_lut_options(CLI::App& app, LutCliOptions& options, const std::string& prefix) {
  app.add_option("--" + prefix + "size", options.bake.size, "LUT width and height in texels")
      ->capture_default_str()
      ->check(CLI::Range(kMinLutSize, kMaxLutSize));
  app.add_option("--" + prefix + "samples", options.bake.samples, "Hammersley samples per texel")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, kMaxLutSamples));
  app.add_option("--" + prefix + "precision", options.precision, "Texel precision")
      ->capture_default_str()
      ->check(CLI::IsMember({"f16", "f32"}));
  add_basis_option(app, options.basis);
}

runtime::BasisKind basis_of(const std::string& basis) {
  return *runtime::basis_from_name(basis);
}

LutPrecision precision_of(const LutCliOptions& options) {
  return *lut_precision_from_name(options.precision);
}

void add_coefficient_table_option(CLI::App& app, LutCliOptions& options) {
  app.add_option("--coefficient-table-precision", options.coefficient_table_precision,
                 "Texel precision of the coefficient table DIR/matc_coefficient_table.<ext>")
      ->capture_default_str()
      ->check(CLI::IsMember({"f16", "f32"}));
}

LutPrecision coefficient_table_precision_of(const LutCliOptions& options) {
  return *lut_precision_from_name(options.coefficient_table_precision);
}

LutWriteCounts write_lut_files(const std::filesystem::path& path, const BakedLut& baked,
                               LutFormat format, LutPrecision precision) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::filesystem::path manifest = path;
  manifest += ".json";
  LutWriteCounts counts;
  for (const auto outcome :
       {write_file_atomically(path, encode_lut(baked, format, precision)),
        write_file_atomically(manifest, format_json(lut_manifest(baked, format, precision)))}) {
    ++(outcome == WriteOutcome::written ? counts.written : counts.unchanged);
  }
  return counts;
}

BuildOptions table_build_options(const LutCliOptions& lut, bool embed_lut,
                                 std::size_t embed_lut_size) {
  BuildOptions build;
  build.lut = lut.bake;
  build.lut_precision = precision_of(lut);
  build.coefficient_table_precision = coefficient_table_precision_of(lut);
  build.embedded_lut_size = embed_lut ? embed_lut_size : 0;
  build.basis = basis_of(lut.basis);
  return build;
}

}  // namespace matc::cli
