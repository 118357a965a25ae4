#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "channel_list.h"
#include "commands.h"
#include "matc/compile.h"
#include "matc/fit/coefficient_table.h"
#include "matc/fit/coefficients.h"
#include "matc/json_format.h"
#include "matc/lut/coefficient_table_files.h"
#include "matc/lut/lut_files.h"
#include "matc/lut/split_sum_reference.h"
#include "matc/material/parse.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/lut.h"
#include "print_diagnostics.h"

namespace matc::cli {
namespace {

using nlohmann::ordered_json;

// Coefficients by the JSON suffix of what they give: "" for a compiled material, "_table" and
// "_compiled" for the coefficient-table path and the per-material compile beside it.
using LabelledCoefficients = std::vector<std::pair<std::string, runtime::Coefficients>>;

// F at each cosine as the shaders compute it, beside the exact curve.
void add_direct_fresnel(const EvalOptions& options, const ReflectanceCurve& curve,
                        const LabelledCoefficients& coefficients, ordered_json& out) {
  const runtime::BasisPolynomial& polynomial =
      runtime::shipped_basis_polynomial(basis_of(options.lut.basis));
  out["mu"] = options.mu;
  for (const auto& [label, values] : coefficients) {
    ordered_json decomposed = ordered_json::array();
    for (const double mu : options.mu)
      decomposed.push_back(runtime::evaluate_fresnel(values, polynomial, mu));
    out["F" + label] = std::move(decomposed);
  }
  ordered_json exact = ordered_json::array();
  for (const double mu : options.mu)
    exact.push_back(curve.at(mu));
  out["F_exact"] = std::move(exact);
}

// Fbar exactly as a renderer samples the table it loads; the reference integrates the exact curve
// directly, without basis or table.
void add_preintegrated_fresnel(const EvalOptions& options, const ReflectanceCurve& curve,
                               const LabelledCoefficients& coefficients,
                               const runtime::BasisView& basis, ordered_json& out) {
  const Lut lut = stored_as(preintegrate_lut(basis, options.lut.bake), precision_of(options.lut));
  out["ndotv"] = options.ndotv;
  out["roughness"] = options.roughness;
  out["lut"] = {{"size", lut.size}, {"samples", lut.samples}, {"precision", options.lut.precision}};
  for (const auto& [label, values] : coefficients) {
    ordered_json fbar = ordered_json::array();
    for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
      fbar.push_back(
          runtime::evaluate_fbar(values, lut.view(), options.ndotv[i], options.roughness[i]));
    }
    out["Fbar" + label] = std::move(fbar);
  }
  const TabulatedCurve tabulated(curve);
  ordered_json reference = ordered_json::array();
  for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
    reference.push_back(
        SplitSumEstimator(options.ndotv[i], options.roughness[i]).integrate(tabulated));
  }
  out["Fbar_reference"] = std::move(reference);
}

// The material a (--reflectivity, --edge-tint) pair stands for: Gulbrandsen's conductor per
// channel.
IorCurve artistic_curve(const std::array<double, 3>& r, const std::array<double, 3>& g) {
  std::array<ComplexIor, 3> ior{};
  for (std::size_t c = 0; c < 3; ++c)
    ior[c] = gulbrandsen_to_ior({r[c], g[c]});
  return IorCurve(ior);
}

// `matc eval --reflectivity R --edge-tint G`: the coefficient-table path beside the compile.
int run_eval_artistic(const EvalOptions& options) {
  if (!options.file.empty()) {
    fmt::print(stderr,
               "matc eval: error: give a material file, or --reflectivity with --edge-tint, not "
               "both\n");
    return kExitUsageError;
  }
  if (options.reflectivity.empty() || options.edge_tint.empty()) {
    fmt::print(stderr, "matc eval: error: --reflectivity and --edge-tint go together: give both\n");
    return kExitUsageError;
  }
  const ChannelList reflectivity_list = parse_channel_list("--reflectivity", options.reflectivity);
  const ChannelList edge_tint_list = parse_channel_list("--edge-tint", options.edge_tint);
  for (const ChannelList* list : {&reflectivity_list, &edge_tint_list}) {
    if (list->values) continue;
    fmt::print(stderr, "matc eval: error: {}\n", list->error);
    return kExitInputError;
  }
  const std::array<double, 3>& reflectivity = *reflectivity_list.values;
  const std::array<double, 3>& edge_tint = *edge_tint_list.values;

  const runtime::BasisKind kind = basis_of(options.lut.basis);
  const runtime::BasisView basis = runtime::shipped_basis(kind);
  const IorCurve curve = artistic_curve(reflectivity, edge_tint);
  // The table as the written file stores it (--coefficient-table-precision).
  const CoefficientTable table =
      stored_coefficient_table(kind, coefficient_table_precision_of(options.lut));
  const LabelledCoefficients coefficients = {
      {"_table", runtime::coefficients_from_table(table.view(), reflectivity, edge_tint)},
      {"_compiled", solve_coefficients(curve, basis)}};

  ordered_json out;
  out["basis"] = runtime::basis_name(kind);
  out["reflectivity"] = reflectivity;
  out["edge_tint"] = edge_tint;
  out["coefficient_table"] = {{"size", table.size()},
                              {"precision", options.lut.coefficient_table_precision}};
  if (!options.mu.empty()) add_direct_fresnel(options, curve, coefficients, out);
  if (!options.ndotv.empty()) add_preintegrated_fresnel(options, curve, coefficients, basis, out);
  fmt::print("{}", format_json(out));
  return kExitSuccess;
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
  if (!options.reflectivity.empty() || !options.edge_tint.empty())
    return run_eval_artistic(options);
  if (options.file.empty()) {
    fmt::print(stderr,
               "matc eval: error: give a material file, or --reflectivity with --edge-tint\n");
    return kExitUsageError;
  }
  const ParseResult parsed = read_material_file(options.file);
  print_diagnostics(parsed.diagnostics);
  if (!parsed.material) return kExitInputError;

  const runtime::BasisView basis = runtime::shipped_basis(basis_of(options.lut.basis));
  const auto curve = make_reflectance_curve(*parsed.material);
  const LabelledCoefficients coefficients = {{"", solve_coefficients(*curve, basis)}};

  ordered_json out;
  out["name"] = parsed.material->name;
  out["basis"] = runtime::basis_name(basis.kind);
  if (!options.mu.empty()) add_direct_fresnel(options, *curve, coefficients, out);
  if (!options.ndotv.empty()) add_preintegrated_fresnel(options, *curve, coefficients, basis, out);
  fmt::print("{}", format_json(out));
  return kExitSuccess;
}

}  // namespace matc::cli
