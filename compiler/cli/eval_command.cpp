#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "matc/compile.h"
#include "matc/fit/coefficients.h"
#include "matc/json_format.h"
#include "matc/lut/lut_files.h"
#include "matc/lut/split_sum_reference.h"
#include "matc/material/parse.h"
#include "matc/runtime/lut.h"
#include "print_diagnostics.h"

namespace matc::cli {
namespace {

using nlohmann::ordered_json;

// F at each cosine as the shaders compute it, beside the exact curve.
void add_direct_fresnel(const EvalOptions& options, const ReflectanceCurve& curve,
                        const runtime::Coefficients& coefficients, ordered_json& out) {
  ordered_json decomposed = ordered_json::array();
  ordered_json exact = ordered_json::array();
  for (const double mu : options.mu) {
    decomposed.push_back(runtime::evaluate_fresnel(
        coefficients, runtime::shipped_basis_polynomial(basis_of(options.lut.basis)), mu));
    exact.push_back(curve.at(mu));
  }
  out["mu"] = options.mu;
  out["F"] = std::move(decomposed);
  out["F_exact"] = std::move(exact);
}

// Fbar exactly as a renderer samples the table it loads; the reference integrates the exact curve
// directly, without basis or table.
void add_preintegrated_fresnel(const EvalOptions& options, const ReflectanceCurve& curve,
                               const runtime::Coefficients& coefficients,
                               const runtime::BasisView& basis, ordered_json& out) {
  const Lut lut = stored_as(preintegrate_lut(basis, options.lut.bake), precision_of(options.lut));
  const TabulatedCurve tabulated(curve);
  ordered_json fbar = ordered_json::array();
  ordered_json reference = ordered_json::array();
  for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
    fbar.push_back(
        runtime::evaluate_fbar(coefficients, lut.view(), options.ndotv[i], options.roughness[i]));
    reference.push_back(
        SplitSumEstimator(options.ndotv[i], options.roughness[i]).integrate(tabulated));
  }
  out["ndotv"] = options.ndotv;
  out["roughness"] = options.roughness;
  out["lut"] = {{"size", lut.size}, {"samples", lut.samples}, {"precision", options.lut.precision}};
  out["Fbar"] = std::move(fbar);
  out["Fbar_reference"] = std::move(reference);
}

}  // namespace

int run_eval(const EvalOptions& options) {
  if (options.mu.empty() && options.ndotv.empty()) {
    fmt::print(stderr, "matc eval: error: give --mu and/or --ndotv with --roughness\n");
    return kExitUsageError;
  }
  if (options.ndotv.size() != options.roughness.size()) {
    fmt::print(stderr,
               "matc eval: error: --ndotv has {} values and --roughness {}; they pair up, so "
               "give as many of each\n",
               options.ndotv.size(), options.roughness.size());
    return kExitUsageError;
  }
  const ParseResult parsed = read_material_file(options.file);
  print_diagnostics(parsed.diagnostics);
  if (!parsed.material) return kExitInputError;

  const runtime::BasisView basis = runtime::shipped_basis(basis_of(options.lut.basis));
  const auto curve = make_reflectance_curve(*parsed.material);
  const runtime::Coefficients coefficients = solve_coefficients(*curve, basis);

  ordered_json out;
  out["name"] = parsed.material->name;
  out["basis"] = runtime::basis_name(basis.kind);
  if (!options.mu.empty()) add_direct_fresnel(options, *curve, coefficients, out);
  if (!options.ndotv.empty()) add_preintegrated_fresnel(options, *curve, coefficients, basis, out);
  fmt::print("{}", format_json(out));
  return kExitSuccess;
}

}  // namespace matc::cli
