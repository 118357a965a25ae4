// matc::api::evaluate: a material evaluated as `matc eval` prints it (the pieces a coated material
// adds are coated_evaluation.cpp's).
#include "matc/api/evaluation.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/json_format.h"
#include "checked_options.h"
#include "checked_values.h"
#include "compile/compile.h"
#include "evaluation_parts.h"
#include "fit/coefficient_table.h"
#include "fit/coefficients.h"
#include "ltc/area_light_reference.h"
#include "ltc/polygon_light.h"
#include "lut/coefficient_table_files.h"
#include "lut/comparison_lobes.h"
#include "lut/film_table_files.h"
#include "lut/lut_files.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/analytic_lut.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/film_table.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/ltc_following.h"
#include "matc/runtime/lut.h"
#include "optics/gulbrandsen.h"

namespace matc::evaluation {
namespace {

// F at each cosine as the shaders compute it, beside the exact curve.
void add_direct_fresnel(const EvaluationInputs& options, const ReflectanceCurve& curve,
                        const LabelledCoefficients& coefficients, ordered_json& out) {
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(options.basis);
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

SplitSumInputs split_sum_inputs(const EvaluationInputs& options, const ReflectanceCurve& curve,
                                const runtime::BasisView& basis) {
  SplitSumInputs inputs{stored_as(preintegrate_lut(basis, options.bake), options.precision),
                        &runtime::shipped_analytic_lut(basis.kind),
                        TabulatedCurve(curve),
                        {}};
  for (std::size_t i = 0; i < options.ndotv.size() && options.reference; ++i) {
    inputs.fbar_reference.push_back(
        SplitSumEstimator(options.ndotv[i], options.roughness[i]).integrate(inputs.tabulated));
  }
  return inputs;
}

// Fbar exactly as a renderer samples the table it loads and from the table's closed form (as
// matc_preintegrated_basis_analytic computes it), beside the exact split-sum integral.
void add_preintegrated_fresnel(const EvaluationInputs& options, const SplitSumInputs& inputs,
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
  if (options.reference) out["Fbar_reference"] = inputs.fbar_reference;
}

// A quad light's references at each point: LTC times the exact split sum (LTC's own error alone)
// and the exact integral over the light of the lobe times the curve, by Monte Carlo.
struct QuadLightReferences {
  ordered_json exact_fresnel = ordered_json::array();
  ordered_json reference = ordered_json::array();
  ordered_json standard_error = ordered_json::array();

  void add(const EvaluationInputs& options, std::size_t i, double integral, runtime::Rgb fbar_exact,
           const std::vector<Vec3>& quad, const TabulatedCurve& tabulated) {
    for (double& channel : fbar_exact)
      channel *= integral;
    exact_fresnel.push_back(fbar_exact);
    const AreaLightEstimate estimate = integrate_polygon_light(
        GgxLobe(options.ndotv[i], options.roughness[i]), quad,
        [&](double mu) { return tabulated.at(mu); }, options.light_samples);
    reference.push_back(estimate.mean);
    standard_error.push_back(estimate.standard_error);
  }

  void write(ordered_json& out) {
    out["L_ltc_exact_fresnel"] = std::move(exact_fresnel);
    out["L_reference"] = std::move(reference);
    out["L_reference_standard_error"] = std::move(standard_error);
  }
};

// A quad light's radiance at each (NdotV, roughness): LTC times Fbar as the shaders compute it
// (ours, per set of coefficients), the quality level's (the lobe's shape and the Fresnel following
// the light, per set of coefficients), LTC times Schlick's split sum, LTC times the exact
// preintegrated Fresnel (LTC's own error alone), and the exact integral.
void add_quad_light(const EvaluationInputs& options, const std::vector<Vec3>& quad,
                    const ReflectanceCurve& curve, const SplitSumInputs& inputs,
                    const LabelledCoefficients& coefficients, const runtime::BasisView& basis,
                    ordered_json& out) {
  const Lut& lut = inputs.lut;
  const TabulatedCurve& tabulated = inputs.tabulated;
  const ComparisonLobes lobes(basis.samples());
  const Lut schlick_lut = preintegrate_lut(lobes.view(), options.bake);
  const runtime::LtcTableView ltc = runtime::shipped_ltc_table();
  const runtime::Rgb f0 = curve.at(1.0);
  add_quad_light_description(options, quad, ltc, out);
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(options.basis);
  std::vector<ordered_json> ours(coefficients.size(), ordered_json::array());
  std::vector<ordered_json> following(coefficients.size(), ordered_json::array());
  ordered_json schlick = ordered_json::array();
  QuadLightReferences references;
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
    runtime::Rgb with_schlick{};
    for (std::size_t c = 0; c < 3; ++c)
      with_schlick[c] = integral * (f0[c] * lobe_values[0] + (1.0 - f0[c]) * lobe_values[1]);
    schlick.push_back(with_schlick);
    if (options.reference)
      references.add(options, i, integral, inputs.fbar_reference[i], quad, tabulated);
  }
  for (std::size_t k = 0; k < coefficients.size(); ++k)
    out["L_ltc" + coefficients[k].first] = std::move(ours[k]);
  for (std::size_t k = 0; k < coefficients.size(); ++k)
    out["L_ltc_following" + coefficients[k].first] = std::move(following[k]);
  out["L_ltc_schlick"] = std::move(schlick);
  if (options.reference) references.write(out);
}

// The material a (--reflectivity, --edge-tint) pair stands for: Gulbrandsen's conductor per
// channel.
IorCurve artistic_curve(const std::array<double, 3>& r, const std::array<double, 3>& g) {
  std::array<ComplexIor, 3> ior{};
  for (std::size_t c = 0; c < 3; ++c)
    ior[c] = gulbrandsen_to_ior({r[c], g[c]});
  return IorCurve(ior);
}

}  // namespace

// The (NdotV, roughness) points and the table a Fbar output was read from.
void add_preintegrated_points(const EvaluationInputs& options, const Lut& lut, ordered_json& out) {
  out["ndotv"] = options.ndotv;
  out["roughness"] = options.roughness;
  out["lut"] = {{"size", lut.size},
                {"samples", lut.samples},
                {"precision", lut_precision_name(options.precision)}};
}

// The quad light and the tables its radiance outputs were computed with.
void add_quad_light_description(const EvaluationInputs& options, const std::vector<Vec3>& quad,
                                const runtime::LtcTableView& ltc, ordered_json& out) {
  ordered_json vertices = ordered_json::array();
  for (const Vec3& vertex : quad)
    vertices.push_back(vertex);
  out["quad_light"] = {{"vertices", std::move(vertices)}, {"ltc_table", {{"size", ltc.size}}}};
  if (options.reference) out["quad_light"]["reference_samples"] = options.light_samples;
}

// A filmed metal's quad light: LTC times the film table's Fbar, as an engine multiplies
// matc_ltc_quad_integral by the film's preintegrated texel (there is no quality level for films:
// it follows the 4-term basis across the lobe), beside LTC times the exact split sum
// (`fbar_reference`, at each point) and the exact integral of the film's curve (`tabulated`),
// both given with options.reference.
void add_film_quad_light(const EvaluationInputs& options, const std::vector<Vec3>& quad,
                         const runtime::FilmTable& table, const TabulatedCurve* tabulated,
                         const std::vector<runtime::Rgb>& fbar_reference, ordered_json& out) {
  const runtime::LtcTableView ltc = runtime::shipped_ltc_table();
  add_quad_light_description(options, quad, ltc, out);
  ordered_json ours = ordered_json::array();
  QuadLightReferences references;
  for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
    const double ndotv = options.ndotv[i], roughness = options.roughness[i];
    ours.push_back(runtime::film_polygon_light_ltc(table, ltc, ndotv, roughness, quad));
    if (!options.reference) continue;
    references.add(options, i,
                   runtime::ltc_polygon_integral(runtime::sample_ltc(ltc, ndotv, roughness), quad),
                   fbar_reference[i], quad, *tabulated);
  }
  out["L_ltc"] = std::move(ours);
  if (options.reference) references.write(out);
}

// A filmed metal (docs/thin-film.md): F and Fbar from its tables as its shader functions read
// them, beside the exact curve and the split sum of it.
void add_filmed(const EvaluationInputs& options, const CompiledMaterial& compiled,
                ordered_json& out) {
  // The table as a file of the table's precision stores it, what a renderer samples; a thickness
  // per pixel's at the thickness asked for (its maximum otherwise: film_table is that slice).
  runtime::FilmTable table = stored_as(*compiled.film_table, options.precision);
  Material material = compiled.material;
  if (compiled.film_stack) {
    const runtime::FilmStack& stack = *compiled.film_stack;
    const double nm = options.film_thickness_nm.value_or(stack.maximum_nm);
    const double t = (nm - stack.minimum_nm) / (stack.maximum_nm - stack.minimum_nm);
    table = runtime::film_stack_table_at(stored_as(stack, options.precision), t);
    material.film->thickness_nm = nm;
    material.film->thickness_minimum_nm.reset();
    out["film_thickness"] = {{"nm", nm}, {"coordinate", t}};
  }
  const auto curve = make_reflectance_curve(material, compiled.color);
  out["film_table"] = {{"size",
                        {runtime::FilmTable::kWidth,
                         compiled.film_stack ? runtime::film_stack_height(*compiled.film_stack)
                                             : runtime::FilmTable::kHeight}},
                       {"precision", lut_precision_name(options.precision)}};
  if (!options.mu.empty()) {
    out["mu"] = options.mu;
    ordered_json ours = ordered_json::array(), exact = ordered_json::array();
    for (const double mu : options.mu) {
      ours.push_back(runtime::film_fresnel(table, mu));
      exact.push_back(curve->at(mu));
    }
    out["F"] = std::move(ours);
    out["F_exact"] = std::move(exact);
  }
  // The exact curve tabulated and its split sum at each point, made once: Fbar's reference and the
  // quad light's read them (as SplitSumInputs does for a bare metal).
  std::optional<TabulatedCurve> tabulated;
  std::vector<runtime::Rgb> fbar_reference;
  if (options.reference && !options.ndotv.empty()) {
    tabulated.emplace(*curve);
    for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
      fbar_reference.push_back(
          SplitSumEstimator(options.ndotv[i], options.roughness[i]).integrate(*tabulated));
    }
  }
  if (!options.ndotv.empty()) {
    out["ndotv"] = options.ndotv;
    out["roughness"] = options.roughness;
    ordered_json fbar = ordered_json::array();
    for (std::size_t i = 0; i < options.ndotv.size(); ++i)
      fbar.push_back(runtime::film_preintegrated(table, options.ndotv[i], options.roughness[i]));
    out["Fbar"] = std::move(fbar);
    if (options.reference) out["Fbar_reference"] = fbar_reference;
  }
  if (options.quad) {
    add_film_quad_light(options, *options.quad, table, tabulated ? &*tabulated : nullptr,
                        fbar_reference, out);
  }
  if (options.metalness) add_metal_rough(options, filmed_metal_lobes(table), out);
}

// A bare metal's F, Fbar and quad light.
std::string evaluate_bare(const EvaluationInputs& options, const Material& material) {
  const runtime::BasisView basis = runtime::shipped_basis(options.basis);
  const ColorOptions color = options.color;
  ordered_json out;
  out["name"] = material.name;
  out["basis"] = runtime::basis_name(basis.kind);
  out["color_space"] = color_space_name(color.working_space);
  if (has_visible_film(material) && !material.coat) {
    add_filmed(options, compile_material(material, basis, color), out);
    return format_json(out);
  }
  if (material.coat) {
    add_coated(options, compile_material(material, basis, color), basis, out);
    return format_json(out);
  }
  const auto curve = make_reflectance_curve(material, color);
  const LabelledCoefficients coefficients = {{"", solve_coefficients(*curve, basis)}};
  if (!options.mu.empty()) add_direct_fresnel(options, *curve, coefficients, out);
  std::optional<SplitSumInputs> inputs;
  if (!options.ndotv.empty()) {
    inputs = split_sum_inputs(options, *curve, basis);
    add_preintegrated_fresnel(options, *inputs, coefficients, out);
    if (options.quad)
      add_quad_light(options, *options.quad, *curve, *inputs, coefficients, basis, out);
  }
  static const Lut kNoTable;  // read only for pairs
  if (options.metalness) {
    add_metal_rough(options,
                    bare_metal_lobes(coefficients.front().second, options.basis,
                                     inputs ? inputs->lut : kNoTable),
                    out);
  }
  return format_json(out);
}

// The coefficient-table path beside the per-material compile.
std::string evaluate_table_path(const EvaluationInputs& options,
                                const std::array<double, 3>& reflectivity,
                                const std::array<double, 3>& edge_tint) {
  const runtime::BasisKind kind = options.basis;
  const runtime::BasisView basis = runtime::shipped_basis(kind);
  const IorCurve curve = artistic_curve(reflectivity, edge_tint);
  // The table as the written file stores it (--coefficient-table-precision).
  const CoefficientTable table =
      stored_coefficient_table(kind, options.coefficient_table_precision);
  const LabelledCoefficients coefficients = {
      {"_table", runtime::coefficients_from_table(table.view(), reflectivity, edge_tint)},
      {"_compiled", solve_coefficients(curve, basis)}};

  ordered_json out;
  out["basis"] = runtime::basis_name(kind);
  out["reflectivity"] = reflectivity;
  out["edge_tint"] = edge_tint;
  out["coefficient_table"] = {{"size", table.size()},
                              {"precision", options.coefficient_table_precision}};
  if (!options.mu.empty()) add_direct_fresnel(options, curve, coefficients, out);
  if (!options.ndotv.empty()) {
    const SplitSumInputs inputs = split_sum_inputs(options, curve, basis);
    add_preintegrated_fresnel(options, inputs, coefficients, out);
    if (options.quad)
      add_quad_light(options, *options.quad, curve, inputs, coefficients, basis, out);
  }
  return format_json(out);
}

}  // namespace matc::evaluation

namespace matc::api {
namespace {

static_assert(kDefaultLightSamples == matc::kDefaultLightSamples);

// The public options checked and resolved; std::invalid_argument names the first problem.
evaluation::EvaluationInputs resolved(const EvaluationOptions& options) {
  if (options.mu.empty() && options.ndotv.empty())
    throw std::invalid_argument(
        "mu, ndotv: both empty; give cosines and/or (NdotV, roughness) pairs");
  check_unit_interval("mu", options.mu);
  check_ndotv_roughness(options.ndotv, options.roughness);
  if (!options.quad_light.empty()) {
    if (options.ndotv.empty())
      throw std::invalid_argument("quad_light: needs (NdotV, roughness) pairs to light");
    if (options.quad_light.size() != 4)
      throw std::invalid_argument(
          fmt::format("quad_light: {} vertices; a quad has 4", options.quad_light.size()));
    const std::string problem = check_polygon_light(options.quad_light);
    if (!problem.empty()) throw std::invalid_argument("quad_light: " + problem);
  }
  evaluation::EvaluationInputs inputs;
  inputs.mu = options.mu;
  inputs.ndotv = options.ndotv;
  inputs.roughness = options.roughness;
  inputs.reference = options.reference;
  if (!options.quad_light.empty()) inputs.quad = options.quad_light;
  inputs.light_samples =
      checked_count("light_samples", options.light_samples, 16, std::size_t{1} << 26);
  inputs.bake.size = checked_count("lut_size", options.lut_size, kMinLutSize, kMaxLutSize);
  inputs.bake.samples = checked_count("lut_samples", options.lut_samples, 1, kMaxLutSamples);
  inputs.precision = option_from_name("lut_precision", options.lut_precision, LutPrecision::f32);
  // `auto` is resolved per material (evaluate()); the coefficient-table path is the first's.
  inputs.basis = basis_choice_of(options.compile).forced;
  inputs.coefficient_table_precision = option_from_name(
      "coefficient_table_precision", options.coefficient_table_precision, LutPrecision::f16);
  inputs.color = color_options_of(options.compile);
  if (options.metalness) {
    check_unit_interval("metalness", std::span<const double>(&*options.metalness, 1));
    inputs.metalness = options.metalness;
  }
  inputs.film_thickness_nm = options.film_thickness;
  return inputs;
}

// --film-thickness names a thickness within the range of a material whose film has one.
void check_film_thickness(const matc::Material& material, const std::optional<double>& nm) {
  if (!nm) return;
  const auto& film = material.film;
  if (!film || !film->thickness_minimum_nm || !has_visible_film(material)) {
    throw std::invalid_argument(
        "film_thickness: the material's film has no thickness range (a thickness per pixel, "
        "docs/thin-film.md); its film is evaluated at its one thickness");
  }
  if (!(*nm >= *film->thickness_minimum_nm && *nm <= film->thickness_nm)) {
    throw std::invalid_argument(
        fmt::format("film_thickness: {} nm is outside the film's range; a thickness in [{}, {}] nm",
                    std::isnan(*nm) ? std::string("NaN") : fmt::format("{}", *nm),
                    *film->thickness_minimum_nm, film->thickness_nm));
  }
}

}  // namespace

std::string evaluate(const Material& material, const EvaluationOptions& options) {
  evaluation::EvaluationInputs inputs = resolved(options);
  check_film_thickness(material.value(), options.film_thickness);
  inputs.basis = basis_for(material.value(), options.compile);
  return evaluation::evaluate_bare(inputs, material.value());
}

std::string evaluate_artistic(const Rgb& reflectivity, const Rgb& edge_tint,
                              const EvaluationOptions& options) {
  check_unit_interval("reflectivity", reflectivity);
  check_unit_interval("edge_tint", edge_tint);
  if (options.metalness)
    throw std::invalid_argument(
        "metalness: the coefficient-table path has no metal-rough mix; evaluate a material");
  if (options.film_thickness)
    throw std::invalid_argument(
        "film_thickness: the coefficient-table path has no film; evaluate a material");
  return evaluation::evaluate_table_path(resolved(options), reflectivity, edge_tint);
}

std::vector<std::array<double, 3>> parse_quad_light(std::string_view text) {
  PolygonLightParse parsed = parse_polygon_light(text, 4);
  if (!parsed.error.empty()) throw std::invalid_argument(parsed.error);
  return std::move(parsed.vertices);
}

}  // namespace matc::api
