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
#include "matc/api/basis.h"
#include "matc/api/diagnostics.h"
#include "matc/api/files.h"
#include "matc/api/options.h"
#include "matc/api/regeneration.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/shipped_bases.h"
#include "name_options.h"
#include "option_help.h"

namespace matc::cli {
namespace {

struct BasisOptions {
  bool json = false;
  std::string basis;  // by name
};

// The subcommands that regenerate checked-in C++ source (api/regeneration.h).
struct RegenerateOptions {
  std::string output;   // empty: standard output
  std::string quality;  // ltc-table: also this CSV, measured with quality_samples per quad
  std::size_t quality_samples = std::size_t{1} << 14;
  api::RegenerationOptions library;
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
      const auto [edge, lobe] = basis.closed_form_exponents;
      fmt::print(
          "shader form: m = 1 - mu, b_1 = m^{}, b_2 = mu m^{}, b_3 = b_2 b_1 (the table is the "
          "closed form sampled)\n",
          edge, lobe);
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

int run_regenerate(api::CheckedInSource source, const RegenerateOptions& options) {
  if (source == api::CheckedInSource::basis_table) {
    // The closed forms have no table: said here in the CLI's words, naming --basis.
    const runtime::BasisKind kind = *runtime::basis_from_name(
        options.library.basis.empty() ? api::option_default("basis") : options.library.basis);
    if (std::find(runtime::kFittedBases.begin(), runtime::kFittedBases.end(), kind) ==
        runtime::kFittedBases.end()) {
      std::vector<std::string_view> fitted;
      for (const runtime::BasisKind each : runtime::kFittedBases)
        fitted.push_back(runtime::basis_name(each));
      fmt::print(stderr,
                 "matc: error: --basis {} is a closed form (runtime/src/powers_basis.cpp) with no "
                 "table to fit; the fitted bases are {}\n",
                 runtime::basis_name(kind), fmt::join(fitted, ", "));
      return kExitUsageError;
    }
  }
  api::RegenerationOptions library = options.library;
  library.quality_samples = options.quality.empty() ? 0 : options.quality_samples;
  const api::RegeneratedSource regenerated = api::regenerate_source(source, library);
  fmt::print(stderr, "matc: {}\n", regenerated.summary);
  if (!options.quality.empty()) {
    try {
      api::write_file(options.quality, regenerated.quality_csv);
    } catch (const std::exception& error) {
      fmt::print(stderr, "{}: error: {}\n", api::printable(options.quality),
                 api::printable(error.what()));
      return kExitInputError;
    }
  }
  return write_generated_source(options.output, regenerated.source);
}

}  // namespace

std::vector<Command> register_basis(CLI::App& app) {
  auto basis = std::make_shared<BasisOptions>();
  CLI::App* basis_command = app.add_subcommand("basis", "Show the Fresnel basis b_0..b_3");
  basis_command->add_flag("--json", basis->json, "Print {mu, b, probes} as JSON");
  add_name_option(*basis_command, "--basis", basis->basis, "basis", kBasisHelp);
  std::vector<Command> commands;
  // -o names where each source lives.
  const auto add_source_command = [&](const char* name, const char* description,
                                      const char* checked_in, api::CheckedInSource source,
                                      bool per_basis) {
    auto options = std::make_shared<RegenerateOptions>();
    CLI::App* command = basis_command->add_subcommand(name, description);
    command->add_option("-o,--output", options->output,
                        fmt::format("Where to write ({}); default stdout", checked_in));
    if (per_basis)
      add_name_option(*command, "--basis", options->library.basis, "basis", kBasisHelp);
    commands.push_back({command, [options, source] { return run_regenerate(source, *options); }});
    return std::pair{command, options};
  };
  add_source_command("fit", "Refit the basis from its training set and write the C++ table source",
                     "runtime/src/generated/<basis>_basis_table.cpp",
                     api::CheckedInSource::basis_table, true);
  add_source_command(
      "coefficient-table",
      "Refit the coefficient table (c_2, c_3 over reflectivity and edge tint) and write its C++ "
      "source",
      "runtime/src/generated/<basis>_coefficient_table.cpp",
      api::CheckedInSource::coefficient_table, true);
  add_source_command(
      "analytic-lut",
      "Bake the basis' default preintegrated table, fit its closed form (the albedo and a "
      "two-point quadrature of the basis, docs/shaders.md) and write the C++ source",
      "runtime/src/generated/<basis>_analytic_lut_table.cpp", api::CheckedInSource::analytic_lut,
      true);
  add_source_command(
      "lut-hashes",
      "Bake the default preintegrated table of every basis and write the C++ source of its "
      "files' hashes (what headers and manifests name without baking)",
      "compiler/src/generated/default_lut_hashes.cpp", api::CheckedInSource::lut_hashes, false);
  add_source_command(
      "material-modules",
      "Compile every basis' material library module with placeholder coefficients and write the "
      "C++ source of those templates (what per-material SPIR-V is patched from)",
      "compiler/src/generated/material_module_templates.cpp",
      api::CheckedInSource::material_modules, false);
  add_source_command(
      "library-modules",
      "Compile the default build's shared library module (matc_fresnel.spv) and write the C++ "
      "source that keeps it, keyed by what its compile reads (a build that matches skips glslang)",
      "compiler/src/generated/library_module_cache.cpp", api::CheckedInSource::library_modules,
      false);
  const auto [ltc_table_command, ltc_table] = add_source_command(
      "ltc-table",
      "Refit the LTC table of GGX (inverse matrices over NdotV and roughness, for area lights) "
      "and write its C++ source",
      "runtime/src/generated/ltc_table.cpp", api::CheckedInSource::ltc_table, false);
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
  ltc_table_command->add_option("-j,--jobs", ltc_table->library.threads,
                                "Threads (default: one per core)");
  add_name_option(*ltc_table_command, "--objective", ltc_table->library.ltc_objective,
                  "ltc_objective",
                  "What the fit minimises: polygons, the error over random quad lights "
                  "(shipped); l1, the densities' L1 distance; or l3, Heitz et al.'s cubed "
                  "difference (docs/ltc.md compares them)");
  commands.push_back({basis_command, [basis] { return run_basis(*basis); }});
  return commands;
}

}  // namespace matc::cli
