#include "matc/api/regeneration.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "basis/basis_fit.h"
#include "checked_options.h"
#include "emit/library_module_cache.h"
#include "emit/material_module_template.h"
#include "fit/coefficient_table.h"
#include "ltc/ltc_fit.h"
#include "lut/analytic_lut_fit.h"
#include "lut/default_lut_hashes.h"
#include "lut/preintegrate.h"
#include "matc/runtime/shipped_bases.h"

namespace matc::api {
namespace {

RegeneratedSource basis_table(runtime::BasisKind kind) {
  const FittedBasis basis = fit_shipped_basis(kind);
  return {basis_table_source(basis),
          fmt::format("fitted basis: probes mu_1 = {:.4f}, mu_2 = {:.4f}", basis.view().probe_mu(0),
                      basis.view().probe_mu(1)),
          {}};
}

RegeneratedSource coefficient_table(runtime::BasisKind kind) {
  const matc::CoefficientTable table = fit_coefficient_table(kind);
  return {coefficient_table_source(table),
          fmt::format("fitted the {} x {} coefficient table of the {} basis", table.size(),
                      table.size(), runtime::basis_name(table.basis)),
          {}};
}

RegeneratedSource analytic_lut(runtime::BasisKind kind) {
  const runtime::BasisView basis = runtime::shipped_basis(kind);
  const Lut table = preintegrate_lut(basis, LutOptions{});
  const runtime::AnalyticLutCoefficients coefficients = fit_analytic_lut(table, kind);
  const AnalyticLutError error = analytic_lut_error(coefficients, table, basis);
  return {analytic_lut_source(kind, coefficients),
          fmt::format("fitted the closed form of the {} basis' table: |Fbar - texture| over the "
                      "measured metals max {:.4f}, mean {:.1e}",
                      runtime::basis_name(kind), error.max, error.mean),
          {}};
}

RegeneratedSource lut_hashes() {
  const std::vector<DefaultLutHash> hashes = compute_default_lut_hashes();
  return {default_lut_hashes_source(hashes),
          fmt::format("hashed {} default table files", hashes.size()),
          {}};
}

RegeneratedSource material_modules() {
  const std::vector<MaterialModuleTemplate> templates = compile_material_module_templates();
  return {material_module_templates_source(templates),
          fmt::format("compiled {} material module templates", templates.size()),
          {}};
}

RegeneratedSource library_modules() {
  const std::vector<CachedLibraryModule> modules = compile_cached_library_modules();
  return {library_module_cache_source(modules),
          fmt::format("compiled {} shared library module{}", modules.size(),
                      modules.size() == 1 ? "" : "s"),
          {}};
}

std::string ltc_quality_csv(const LtcTable& table, std::size_t samples, unsigned threads) {
  const std::vector<double> polygon = ltc_polygon_errors(table.view(), samples, threads);
  std::string csv = "x,y,ndotv,roughness,l1_distance,cubed_distance,polygon_error\n";
  for (std::size_t y = 0; y < table.size; ++y) {
    for (std::size_t x = 0; x < table.size; ++x) {
      const std::size_t i = y * table.size + x;
      csv += fmt::format("{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", x, y,
                         ltc_texel_ndotv(x, table.size), ltc_texel_roughness(y, table.size),
                         table.l1_distance[i], table.cubed_distance[i], polygon[i]);
    }
  }
  return csv;
}

RegeneratedSource ltc_table(const RegenerationOptions& options) {
  const LtcObjective objective =
      option_from_name("ltc_objective", options.ltc_objective, LtcObjective::polygons);
  const LtcTable table =
      fit_ltc_table({.size = kDefaultLtcSize, .threads = options.threads, .objective = objective});
  RegeneratedSource out{ltc_table_source(table),
                        fmt::format("fitted the {} x {} LTC table", table.size, table.size),
                        {}};
  if (options.quality_samples != 0)
    out.quality_csv = ltc_quality_csv(table, options.quality_samples, options.threads);
  return out;
}

}  // namespace

RegeneratedSource regenerate_source(CheckedInSource source, const RegenerationOptions& options) {
  const runtime::BasisKind kind = basis_of({options.basis, {}, {}});
  switch (source) {
    case CheckedInSource::basis_table:
      if (std::find(runtime::kFittedBases.begin(), runtime::kFittedBases.end(), kind) ==
          runtime::kFittedBases.end())
        throw std::invalid_argument(fmt::format("basis: {} is a closed form with no table to fit",
                                                runtime::basis_name(kind)));
      return basis_table(kind);
    case CheckedInSource::coefficient_table:
      return coefficient_table(kind);
    case CheckedInSource::analytic_lut:
      return analytic_lut(kind);
    case CheckedInSource::lut_hashes:
      return lut_hashes();
    case CheckedInSource::material_modules:
      return material_modules();
    case CheckedInSource::library_modules:
      return library_modules();
    case CheckedInSource::ltc_table:
      return ltc_table(options);
  }
  throw std::invalid_argument("source: not a CheckedInSource");
}

}  // namespace matc::api
