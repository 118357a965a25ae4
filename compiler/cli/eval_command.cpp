#include <optional>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "channel_list.h"
#include "color_options.h"
#include "commands.h"
#include "eval_options.h"
#include "lut_options.h"
#include "matc/base/echoed_text.h"
#include "matc/base/json_format.h"
#include "matc/compile/compile.h"
#include "matc/fit/coefficient_table.h"
#include "matc/fit/coefficients.h"
#include "matc/ltc/area_light_reference.h"
#include "matc/ltc/polygon_light.h"
#include "matc/lut/coefficient_table_files.h"
#include "matc/lut/comparison_lobes.h"
#include "matc/lut/layered_reference.h"
#include "matc/lut/lut_files.h"
#include "matc/lut/split_sum_reference.h"
#include "matc/material/material_input.h"
#include "matc/optics/coat.h"
#include "matc/runtime/analytic_lut.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/ltc_following.h"
#include "matc/runtime/lut.h"
#include "print_diagnostics.h"

namespace matc::cli {
namespace {

// F at each cosine as the shaders compute it, beside the exact curve.
void add_direct_fresnel(const EvalOptions& options, const ReflectanceCurve& curve,
                        const LabelledCoefficients& coefficients, ordered_json& out) {
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(options.lut.basis);
  out["mu"] = options.mu;
  for (const auto& [label, values] : coefficients) {
    ordered_json decomposed = ordered_json::array();
    for (const double mu : options.mu)
      decomposed.push_back(runtime::evaluate_fresnel(values, shader_basis, mu));
    out["F" + label] = std::move(decomposed);
  }
  ordered_json exact = ordered_json::array();
  for (const double mu : options.mu)
    exact.push_back(curve.at(mu));
  out["F_exact"] = std::move(exact);
}

// What Fbar and the quad light both read, made once: the table as a renderer loads it, the exact
// curve tabulated, and its split-sum integral at each (NdotV, roughness), without basis or table.
struct SplitSumInputs {
  Lut lut;
  const runtime::AnalyticLutCoefficients* analytic;  // the table's closed form
  TabulatedCurve tabulated;
  std::vector<runtime::Rgb> fbar_reference;
};

SplitSumInputs split_sum_inputs(const EvalOptions& options, const ReflectanceCurve& curve,
                                const runtime::BasisView& basis) {
  SplitSumInputs inputs{stored_as(preintegrate_lut(basis, options.lut.bake), options.lut.precision),
                        &runtime::shipped_analytic_lut(basis.kind),
                        TabulatedCurve(curve),
                        {}};
  for (std::size_t i = 0; i < options.ndotv.size() && !options.no_reference; ++i) {
    inputs.fbar_reference.push_back(
        SplitSumEstimator(options.ndotv[i], options.roughness[i]).integrate(inputs.tabulated));
  }
  return inputs;
}

// Fbar exactly as a renderer samples the table it loads and from the table's closed form (as
// matc_preintegrated_basis_analytic computes it), beside the exact split-sum integral.
void add_preintegrated_fresnel(const EvalOptions& options, const SplitSumInputs& inputs,
                               const LabelledCoefficients& coefficients, ordered_json& out) {
  const Lut& lut = inputs.lut;
  add_preintegrated_points(options, lut, out);
  for (const auto& [label, values] : coefficients) {
    ordered_json fbar = ordered_json::array();
    for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
      fbar.push_back(
          runtime::evaluate_fbar(values, lut.view(), options.ndotv[i], options.roughness[i]));
    }
    out["Fbar" + label] = std::move(fbar);
    ordered_json analytic = ordered_json::array();
    for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
      analytic.push_back(runtime::evaluate_fbar_analytic(values, *inputs.analytic, options.ndotv[i],
                                                         options.roughness[i]));
    }
    out["Fbar_analytic" + label] = std::move(analytic);
  }
  if (!options.no_reference) out["Fbar_reference"] = inputs.fbar_reference;
}

// A quad light's radiance at each (NdotV, roughness): LTC times Fbar as the shaders compute it
// (ours, per set of coefficients), the quality level's (the lobe's shape and the Fresnel following
// the light, per set of coefficients), LTC times Schlick's split sum, LTC times the exact
// preintegrated Fresnel (LTC's own error alone), and the exact integral.
void add_quad_light(const EvalOptions& options, const std::vector<Vec3>& quad,
                    const ReflectanceCurve& curve, const SplitSumInputs& inputs,
                    const LabelledCoefficients& coefficients, const runtime::BasisView& basis,
                    ordered_json& out) {
  const Lut& lut = inputs.lut;
  const TabulatedCurve& tabulated = inputs.tabulated;
  const ComparisonLobes lobes(basis.samples());
  const Lut schlick_lut = preintegrate_lut(lobes.view(), options.lut.bake);
  const runtime::LtcTableView ltc = runtime::shipped_ltc_table();
  const runtime::Rgb f0 = curve.at(1.0);
  add_quad_light_description(options, quad, ltc, out);
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(options.lut.basis);
  std::vector<ordered_json> ours(coefficients.size(), ordered_json::array());
  std::vector<ordered_json> following(coefficients.size(), ordered_json::array());
  ordered_json schlick = ordered_json::array(), exact_fresnel = ordered_json::array(),
               reference = ordered_json::array(), standard_error = ordered_json::array();
  for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
    const double ndotv = options.ndotv[i], roughness = options.roughness[i];
    const double integral =
        runtime::ltc_polygon_integral(runtime::sample_ltc(ltc, ndotv, roughness), quad);
    for (std::size_t k = 0; k < coefficients.size(); ++k) {
      ours[k].push_back(runtime::polygon_light_ltc(coefficients[k].second, lut.view(), ltc, ndotv,
                                                   roughness, quad));
      following[k].push_back(runtime::polygon_light_ltc_following(
          coefficients[k].second, lut.view(), shader_basis, ltc, ndotv, roughness, quad));
    }
    const auto lobe_values = runtime::sample_lut(schlick_lut.view(), ndotv, roughness);
    const runtime::Rgb& fbar_exact = inputs.fbar_reference[i];
    runtime::Rgb with_schlick{}, with_exact{};
    for (std::size_t c = 0; c < 3; ++c) {
      with_schlick[c] = integral * (f0[c] * lobe_values[0] + (1.0 - f0[c]) * lobe_values[1]);
      with_exact[c] = integral * fbar_exact[c];
    }
    schlick.push_back(with_schlick);
    exact_fresnel.push_back(with_exact);
    const AreaLightEstimate estimate = integrate_polygon_light(
        GgxLobe(ndotv, roughness), quad, [&](double mu) { return tabulated.at(mu); },
        options.light_samples);
    reference.push_back(estimate.mean);
    standard_error.push_back(estimate.standard_error);
  }
  for (std::size_t k = 0; k < coefficients.size(); ++k)
    out["L_ltc" + coefficients[k].first] = std::move(ours[k]);
  for (std::size_t k = 0; k < coefficients.size(); ++k)
    out["L_ltc_following" + coefficients[k].first] = std::move(following[k]);
  out["L_ltc_schlick"] = std::move(schlick);
  out["L_ltc_exact_fresnel"] = std::move(exact_fresnel);
  out["L_reference"] = std::move(reference);
  out["L_reference_standard_error"] = std::move(standard_error);
}

// The quad of --quad-light, or the message for a bad one (printed here).
std::optional<std::vector<Vec3>> quad_light_of(const EvalOptions& options) {
  const PolygonLightParse parsed = parse_polygon_light(options.quad_light, 4);
  if (parsed.error.empty()) return parsed.vertices;
  fmt::print(stderr, "matc eval: error: --quad-light: {}\n", parsed.error);
  return std::nullopt;
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
  std::optional<std::vector<Vec3>> quad;
  if (!options.quad_light.empty() && !(quad = quad_light_of(options))) return kExitInputError;

  const runtime::BasisKind kind = options.lut.basis;
  const runtime::BasisView basis = runtime::shipped_basis(kind);
  const IorCurve curve = artistic_curve(reflectivity, edge_tint);
  // The table as the written file stores it (--coefficient-table-precision).
  const CoefficientTable table =
      stored_coefficient_table(kind, options.lut.coefficient_table_precision);
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
  if (!options.ndotv.empty()) {
    const SplitSumInputs inputs = split_sum_inputs(options, curve, basis);
    add_preintegrated_fresnel(options, inputs, coefficients, out);
    if (quad) add_quad_light(options, *quad, curve, inputs, coefficients, basis, out);
  }
  fmt::print("{}", format_json(out));
  return kExitSuccess;
}

// The material to evaluate: the file's only one, or the document's material named --material.
std::optional<Material> chosen_material(const EvalOptions& options) {
  MaterialInput input = read_material_input(options.file);
  print_diagnostics(input.diagnostics);
  if (input.materials.empty()) return std::nullopt;
  std::string names;
  for (const Material& material : input.materials) {
    if (material.name == options.material ||
        (options.material.empty() && input.materials.size() == 1))
      return material;
    names += fmt::format("{}{}", names.empty() ? "" : ", ", material.name);
  }
  if (options.material.empty()) {
    fmt::print(stderr, "matc eval: error: {} holds {} materials ({}): name one with --material\n",
               printable(options.file), input.materials.size(), names);
  } else {
    fmt::print(stderr, "matc eval: error: --material: {} holds no material '{}' (it holds {})\n",
               printable(options.file), echoed(options.material), names);
  }
  return std::nullopt;
}

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
  std::optional<std::vector<Vec3>> quad;
  if (!options.quad_light.empty() && !(quad = quad_light_of(options))) return kExitInputError;
  const std::optional<Material> material = chosen_material(options);
  if (!material) return kExitInputError;

  const runtime::BasisView basis = runtime::shipped_basis(options.lut.basis);
  const ColorOptions color = options.color;
  if (material->coat) {
    ordered_json out;
    out["name"] = material->name;
    out["basis"] = runtime::basis_name(basis.kind);
    out["color_space"] = color_space_name(color.working_space);
    add_coated(options, compile_material(*material, basis, color), basis, quad, out);
    fmt::print("{}", format_json(out));
    return kExitSuccess;
  }
  const auto curve = make_reflectance_curve(*material, color);
  const LabelledCoefficients coefficients = {{"", solve_coefficients(*curve, basis)}};

  ordered_json out;
  out["name"] = material->name;
  out["basis"] = runtime::basis_name(basis.kind);
  out["color_space"] = color_space_name(color.working_space);
  if (!options.mu.empty()) add_direct_fresnel(options, *curve, coefficients, out);
  if (!options.ndotv.empty()) {
    const SplitSumInputs inputs = split_sum_inputs(options, *curve, basis);
    add_preintegrated_fresnel(options, inputs, coefficients, out);
    if (quad) add_quad_light(options, *quad, *curve, inputs, coefficients, basis, out);
  }
  fmt::print("{}", format_json(out));
  return kExitSuccess;
}

}  // namespace

Command register_eval(CLI::App& app) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* command =
      app.add_subcommand("eval", "Evaluate a material's decomposed and exact Fresnel as JSON");
  command->add_option("file", options->file,
                      "Material file (.json) or MaterialX document (.mtlx); or give "
                      "--reflectivity and --edge-tint");
  command->add_option("--material", options->material,
                      "Which material of a MaterialX document (its name as imported); needed "
                      "when the document holds more than one");
  command->add_option("--reflectivity", options->reflectivity,
                      "Gulbrandsen reflectivity r per channel (R,G,B or one grey value in "
                      "[0, 1]): F from the coefficient table beside the per-material compile");
  command->add_option("--edge-tint", options->edge_tint,
                      "Gulbrandsen edge tint g per channel, with --reflectivity");
  command->add_option("--mu", options->mu, "Cosines of incidence, comma-separated: F")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1.0));
  CLI::Option* ndotv_option =
      command->add_option("--ndotv", options->ndotv, "NdotV values, comma-separated: Fbar")
          ->delimiter(',')
          ->check(CLI::Range(0.0, 1.0));
  CLI::Option* roughness_option =
      command
          ->add_option("--roughness", options->roughness,
                       "Perceptual roughness for each --ndotv value, comma-separated")
          ->delimiter(',')
          ->check(CLI::Range(0.0, 1.0));
  ndotv_option->needs(roughness_option);
  roughness_option->needs(ndotv_option);
  options->light_samples = matc::kDefaultLightSamples;
  CLI::Option* no_reference_option = command->add_flag(
      "--no-reference", options->no_reference,
      "Leave out Fbar_reference, the exact split-sum integral per --ndotv value (a Monte-Carlo "
      "integral each: the slow part of evaluating many points)");
  command
      ->add_option("--quad-light", options->quad_light,
                   "A quad light of radiance 1, \"x,y,z;x,y,z;x,y,z;x,y,z\" in the shading frame "
                   "(normal +z, view in the xz-plane towards +x): radiance by LTC with ours (one "
                   "shape, and the quality level's shape and Fresnel following the light) and "
                   "with Schlick's Fresnel, and the exact integral (docs/ltc.md)")
      ->needs(ndotv_option)
      ->excludes(no_reference_option);
  command
      ->add_option("--light-samples", options->light_samples,
                   "Monte-Carlo sample pairs of the --quad-light reference")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{16}, std::size_t{1} << 26));
  add_lut_options(*command, options->lut, "lut-");
  add_coefficient_table_option(*command, options->lut);
  add_color_options(*command, options->color);

  return {command, [options] { return run_eval(*options); }, true};
}

}  // namespace matc::cli
