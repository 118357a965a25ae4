#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <fmt/core.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "generated_source.h"
#include "lut_options.h"
#include "matc/api/basis.h"
#include "matc/api/diagnostics.h"
#include "matc/api/files.h"
#include "matc/basis/basis_fit.h"
#include "matc/emit/material_module_template.h"
#include "matc/fit/coefficient_table.h"
#include "matc/ltc/ltc_fit.h"
#include "matc/lut/analytic_lut_fit.h"
#include "matc/lut/default_lut_hashes.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/shipped_bases.h"
#include "name_options.h"
#include "named_option.h"
#include "option_help.h"

namespace matc::cli {
namespace {

struct BasisOptions {
  bool json = false;
  std::string basis;  // by name
};

struct BasisFitOptions {
  std::string output;  // empty: standard output
  runtime::BasisKind basis = runtime::kDefaultBasis;
};

// `matc basis ltc-table`: refits the shipped LTC table, writes its C++ source and, on request,
// each texel's fit quality as CSV.
struct LtcTableOptions {
  std::string output;
  std::string quality;
  std::size_t quality_samples = 1u << 14;
  unsigned jobs = 0;
  LtcObjective objective = LtcObjective::polygons;  // shipped; l1 or l3 (Heitz et al.'s)
};

int run_basis(const BasisOptions& options) {
  const api::BasisDescription basis = api::describe_basis(options.basis);
  if (!options.json) {
    const std::size_t samples = basis.mu.size();
    fmt::print("basis: {} ({}), b_0 = 1 and b_1..b_3 {}\n", basis.name, basis.description,
               basis.closed_form ? "in closed form" : "tabulated");
    fmt::print("samples: {} cosines mu_j = j / {}\n", samples, samples - 1);
    fmt::print("probes: mu_1 = {:.4f} (theta {:.3f} rad), mu_2 = {:.4f} (theta {:.3f} rad)\n",
               basis.probes[0], std::acos(basis.probes[0]), basis.probes[1],
               std::acos(basis.probes[1]));
    if (basis.closed_form) {
      fmt::print(
          "shader form: m = 1 - mu, b_1 = m^6, b_2 = mu m^3, b_3 = b_2 b_1 (the table is the "
          "closed form sampled)\n");
      return kExitSuccess;
    }
    const auto& at = basis.polynomial_error_at_samples;
    const auto& between = basis.polynomial_error_between_samples;
    fmt::print(
        "shader form: {} polynomials of degree {} in sqrt(mu); max |polynomial - table| for "
        "b_1, b_2, b_3: {:.1e}, {:.1e}, {:.1e} at the samples, {:.1e}, {:.1e}, {:.1e} between "
        "them\n",
        runtime::kPolynomialSegments, runtime::kPolynomialDegree, at[0], at[1], at[2], between[0],
        between[1], between[2]);
    return kExitSuccess;
  }
  // Built apart and moved in: ordered_json keeps members in a vector, so references into `out`
  // would dangle as members are added.
  std::vector<nlohmann::ordered_json> b(runtime::kBasisSize, nlohmann::ordered_json::array());
  for (const auto& values : basis.b)
    for (std::size_t i = 0; i < runtime::kBasisSize; ++i)
      b[i].push_back(values[i]);
  nlohmann::ordered_json out;
  out["mu"] = basis.mu;
  out["b"] = std::move(b);
  out["probes"] = basis.probes;
  fmt::print("{}\n", out.dump());
  return kExitSuccess;
}

int run_basis_fit(const BasisFitOptions& options) {
  const runtime::BasisKind kind = options.basis;
  if (std::find(runtime::kFittedBases.begin(), runtime::kFittedBases.end(), kind) ==
      runtime::kFittedBases.end()) {
    std::vector<std::string_view> fitted;
    for (const runtime::BasisKind each : runtime::kFittedBases)
      fitted.push_back(runtime::basis_name(each));
    fmt::print(stderr,
               "matc: error: --basis {} is a closed form (runtime/src/{}_basis.cpp) with no table "
               "to fit; the fitted bases are {}\n",
               runtime::basis_name(kind), runtime::basis_name(kind), fmt::join(fitted, ", "));
    return kExitUsageError;
  }
  const FittedBasis basis = fit_shipped_basis(kind);
  fmt::print(stderr, "matc: fitted basis: probes mu_1 = {:.4f}, mu_2 = {:.4f}\n",
             basis.view().probe_mu(0), basis.view().probe_mu(1));
  return write_generated_source(options.output, basis_table_source(basis));
}

int run_basis_coefficient_table(const BasisFitOptions& options) {
  const CoefficientTable table = fit_coefficient_table(options.basis);
  fmt::print(stderr, "matc: fitted the {} x {} coefficient table of the {} basis\n", table.size(),
             table.size(), runtime::basis_name(table.basis));
  return write_generated_source(options.output, coefficient_table_source(table));
}

int run_basis_lut_hashes(const BasisFitOptions& options) {
  const std::vector<DefaultLutHash> hashes = compute_default_lut_hashes();
  fmt::print(stderr, "matc: hashed {} default table files\n", hashes.size());
  return write_generated_source(options.output, default_lut_hashes_source(hashes));
}

int run_basis_analytic_lut(const BasisFitOptions& options) {
  const runtime::BasisKind kind = options.basis;
  const runtime::BasisView basis = runtime::shipped_basis(kind);
  const Lut table = preintegrate_lut(basis, LutOptions{});
  const runtime::AnalyticLutCoefficients coefficients = fit_analytic_lut(table, kind);
  const AnalyticLutError error = analytic_lut_error(coefficients, table, basis);
  fmt::print(stderr,
             "matc: fitted the closed form of the {} basis' table: |Fbar - texture| over the "
             "measured metals max {:.4f}, mean {:.1e}\n",
             runtime::basis_name(kind), error.max, error.mean);
  return write_generated_source(options.output, analytic_lut_source(kind, coefficients));
}

int run_basis_material_modules(const BasisFitOptions& options) {
  const std::vector<MaterialModuleTemplate> templates = compile_material_module_templates();
  fmt::print(stderr, "matc: compiled {} material module templates\n", templates.size());
  return write_generated_source(options.output, material_module_templates_source(templates));
}

int run_basis_ltc_table(const LtcTableOptions& options) {
  const LtcTable table = fit_ltc_table(
      {.size = kDefaultLtcSize, .threads = options.jobs, .objective = options.objective});
  fmt::print(stderr, "matc: fitted the {} x {} LTC table\n", table.size, table.size);
  if (!options.quality.empty()) {
    const std::vector<double> polygon =
        ltc_polygon_errors(table.view(), options.quality_samples, options.jobs);
    std::string csv = "x,y,ndotv,roughness,l1_distance,cubed_distance,polygon_error\n";
    for (std::size_t y = 0; y < table.size; ++y) {
      for (std::size_t x = 0; x < table.size; ++x) {
        const std::size_t i = y * table.size + x;
        csv += fmt::format("{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", x, y,
                           ltc_texel_ndotv(x, table.size), ltc_texel_roughness(y, table.size),
                           table.l1_distance[i], table.cubed_distance[i], polygon[i]);
      }
    }
    try {
      api::write_file(options.quality, csv);
    } catch (const std::exception& error) {
      fmt::print(stderr, "{}: error: {}\n", api::printable(options.quality),
                 api::printable(error.what()));
      return kExitInputError;
    }
  }
  return write_generated_source(options.output, ltc_table_source(table));
}

}  // namespace

std::vector<Command> register_basis(CLI::App& app) {
  auto basis = std::make_shared<BasisOptions>();
  CLI::App* basis_command = app.add_subcommand("basis", "Show the Fresnel basis b_0..b_3");
  basis_command->add_flag("--json", basis->json, "Print {mu, b, probes} as JSON");
  add_name_option(*basis_command, "--basis", basis->basis, "basis", kBasisHelp);
  std::vector<Command> commands;
  // The subcommands that regenerate checked-in C++ source: -o names where it lives.
  const auto add_source_command = [&](const char* name, const char* description,
                                      const char* checked_in, bool per_basis,
                                      int (*run)(const BasisFitOptions&)) {
    auto options = std::make_shared<BasisFitOptions>();
    CLI::App* command = basis_command->add_subcommand(name, description);
    command->add_option("-o,--output", options->output,
                        fmt::format("Where to write ({}); default stdout", checked_in));
    if (per_basis) add_basis_option(*command, options->basis);
    commands.push_back({command, [options, run] { return run(*options); }});
  };
  add_source_command("fit", "Refit the basis from its training set and write the C++ table source",
                     "runtime/src/generated/<basis>_basis_table.cpp", true, run_basis_fit);
  add_source_command(
      "coefficient-table",
      "Refit the coefficient table (c_2, c_3 over reflectivity and edge tint) and write its C++ "
      "source",
      "runtime/src/generated/<basis>_coefficient_table.cpp", true, run_basis_coefficient_table);
  add_source_command(
      "analytic-lut",
      "Bake the basis' default preintegrated table, fit its closed form (the albedo and a "
      "two-point quadrature of the basis, docs/shaders.md) and write the C++ source",
      "runtime/src/generated/<basis>_analytic_lut_table.cpp", true, run_basis_analytic_lut);
  add_source_command(
      "lut-hashes",
      "Bake the default preintegrated table of every basis and write the C++ source of its "
      "files' hashes (what headers and manifests name without baking)",
      "compiler/src/generated/default_lut_hashes.cpp", false, run_basis_lut_hashes);
  add_source_command(
      "material-modules",
      "Compile every basis' material library module with placeholder coefficients and write the "
      "C++ source of those templates (what per-material SPIR-V is patched from)",
      "compiler/src/generated/material_module_templates.cpp", false, run_basis_material_modules);

  auto ltc_table = std::make_shared<LtcTableOptions>();
  CLI::App* ltc_table_command = basis_command->add_subcommand(
      "ltc-table",
      "Refit the LTC table of GGX (inverse matrices over NdotV and roughness, for area lights) "
      "and write its C++ source");
  ltc_table_command->add_option(
      "-o,--output", ltc_table->output,
      "Where to write (runtime/src/generated/ltc_table.cpp); default stdout");
  ltc_table_command
      ->add_option("--quality", ltc_table->quality,
                   "Also write each texel's fit quality as CSV (distribution and polygon-light "
                   "errors: docs/ltc.md)")
      ->check(CLI::NonexistentPath | CLI::ExistingFile);
  ltc_table_command
      ->add_option("--quality-samples", ltc_table->quality_samples,
                   "Reference samples per polygon for --quality")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{64}, std::size_t{1} << 24));
  ltc_table_command->add_option("-j,--jobs", ltc_table->jobs, "Threads (default: one per core)");
  add_named_option(*ltc_table_command, "--objective", ltc_table->objective,
                   "What the fit minimises: polygons, the error over random quad lights "
                   "(shipped); l1, the densities' L1 distance; or l3, Heitz et al.'s cubed "
                   "difference (docs/ltc.md compares them)");
  commands.push_back({ltc_table_command, [ltc_table] { return run_basis_ltc_table(*ltc_table); }});
  commands.push_back({basis_command, [basis] { return run_basis(*basis); }});
  return commands;
}

}  // namespace matc::cli
