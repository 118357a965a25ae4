// matc::api::evaluate for a coated material (matc eval of a material with a coat).
#include <functional>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "compile/compile.h"
#include "evaluation_parts.h"
#include "ltc/area_light_reference.h"
#include "lut/film_table_files.h"
#include "lut/layered_reference.h"
#include "lut/lut_files.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/analytic_lut.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/lut.h"
#include "optics/coat.h"

namespace matc::evaluation {
namespace {

// A quad light on a coated material's two lobes: LTC per lobe times its Fbar as the shaders
// compute it (matc_ltc_quad_light_<name>), and the exact integral of each lobe (the base's with
// the exact layered base curve at its half vectors, the coat's with the coat's exact Fresnel).
// `lit` gives both lobes under the light at (NdotV, roughness), as the shaders compute them.
using LitLobes = std::function<runtime::CoatedFresnel(double ndotv, double roughness)>;
void add_coated_quad_light(const EvaluationInputs& options, const std::vector<Vec3>& quad,
                           const CompiledMaterial& compiled, const LitLobes& lit,
                           const ReflectanceCurve& in_air, const ReflectanceCurve& under,
                           ordered_json& out) {
  const CoatInput& coat = compiled.coat->input;
  const runtime::LtcTableView ltc = runtime::shipped_ltc_table();
  // The exact lobes the reference integrates, tabulated only when it is asked for.
  std::optional<TabulatedCurve> base_table, coat_table;
  if (options.reference) {
    base_table.emplace(
        LayeredCurve(in_air, under, coat.weight, coat.ior, coat.color, LayeredCurve::Part::base));
    coat_table.emplace(
        LayeredCurve(in_air, under, coat.weight, coat.ior, coat.color, LayeredCurve::Part::coat));
  }
  add_quad_light_description(options, quad, ltc, out);
  ordered_json ours = ordered_json::array(), ours_base = ordered_json::array(),
               ours_coat = ordered_json::array(), reference = ordered_json::array(),
               standard_error = ordered_json::array();
  for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
    const double ndotv = options.ndotv[i], roughness = options.roughness[i];
    const runtime::CoatedFresnel lobes = lit(ndotv, roughness);
    ours.push_back(lobes.total());
    ours_base.push_back(lobes.base);
    ours_coat.push_back(lobes.coat);
    if (!options.reference) continue;
    const AreaLightEstimate base_part = integrate_polygon_light(
        GgxLobe(ndotv, roughness), quad, [&](double mu) { return base_table->at(mu); },
        options.light_samples);
    const AreaLightEstimate coat_part = integrate_polygon_light(
        GgxLobe(ndotv, coat.roughness), quad, [&](double mu) { return coat_table->at(mu); },
        options.light_samples);
    Rgb sum{}, error{};
    for (std::size_t c = 0; c < 3; ++c) {
      sum[c] = base_part.mean[c] + coat_part.mean[c];
      error[c] = std::hypot(base_part.standard_error[c], coat_part.standard_error[c]);
    }
    reference.push_back(sum);
    standard_error.push_back(error);
  }
  out["L_ltc"] = std::move(ours);
  // Each lobe's part (engines that scale the base's lights for multiple scattering need them
  // apart).
  out["L_ltc_base"] = std::move(ours_base);
  out["L_ltc_coat"] = std::move(ours_coat);
  if (!options.reference) return;
  out["L_reference"] = std::move(reference);
  out["L_reference_standard_error"] = std::move(standard_error);
}

}  // namespace

// A coated material (docs/coating.md): both lobes as the shaders compute them and their sum,
// beside the exact layered curve (smooth interfaces); preintegrated, the same beside the split
// sum of each exact lobe at its own roughness and the Monte-Carlo layered reference (rough
// interfaces, any number of bounces, no split sum).
void add_coated(const EvaluationInputs& options, const CompiledMaterial& compiled,
                const runtime::BasisView& basis, ordered_json& out) {
  const Material& material = compiled.material;
  const CompiledCoat& coat = *compiled.coat;
  const runtime::CoatCoefficients& coefficients = coat.coefficients;
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(basis.kind);
  const auto in_air = make_reflectance_curve(material, options.color);
  const auto under = make_under_coat_curve(material, options.color.working_space);
  const auto metal_in_coat = make_metal_in_coat_curve(material, options.color.working_space);
  // A film under the coat: the base lobe from its table as a file of the table's precision
  // stores it (what a renderer samples); no closed form.
  std::optional<runtime::FilmTable> film;
  if (compiled.film_table) {
    film = stored_as(*compiled.film_table, options.precision);
    out["film_table"] = {{"size", {runtime::FilmTable::kWidth, runtime::FilmTable::kHeight}},
                         {"precision", lut_precision_name(options.precision)}};
  }
  const auto fresnel_lobes = [&](double mu) {
    return film ? runtime::evaluate_film_coated_fresnel(*film, coefficients, shader_basis, mu)
                : runtime::evaluate_coated_fresnel(compiled.coefficients, coefficients,
                                                   shader_basis, mu);
  };
  const auto fbar_lobes = [&](const runtime::LutView& lut, double ndotv, double roughness) {
    return film ? runtime::evaluate_film_coated_fbar(*film, coefficients, lut, ndotv, roughness)
                : runtime::evaluate_coated_fbar(compiled.coefficients, coefficients, lut, ndotv,
                                                roughness);
  };
  out["coat"] = {{"weight", coat.input.weight},
                 {"ior", coat.input.ior},
                 {"roughness", coat.input.roughness},
                 {"color", coat.input.color}};
  if (!options.mu.empty()) {
    out["mu"] = options.mu;
    ordered_json total = ordered_json::array(), base = ordered_json::array(),
                 coat_lobe = ordered_json::array(), exact = ordered_json::array(),
                 exact_base = ordered_json::array(), exact_coat = ordered_json::array();
    const auto layered = [&](LayeredCurve::Part part) {
      return LayeredCurve(*in_air, *under, coat.input.weight, coat.input.ior, coat.input.color,
                          part);
    };
    const LayeredCurve both = layered(LayeredCurve::Part::both);
    const LayeredCurve base_part = layered(LayeredCurve::Part::base);
    const LayeredCurve coat_part = layered(LayeredCurve::Part::coat);
    for (const double mu : options.mu) {
      const auto lobes = fresnel_lobes(mu);
      total.push_back(lobes.total());
      base.push_back(lobes.base);
      coat_lobe.push_back(lobes.coat);
      exact.push_back(both.at(mu));
      exact_base.push_back(base_part.at(mu));
      exact_coat.push_back(coat_part.at(mu)[0]);
    }
    out["F"] = std::move(total);
    out["F_base"] = std::move(base);
    out["F_coat"] = std::move(coat_lobe);
    out["F_exact"] = std::move(exact);
    // Each lobe's exact curve apart (a reference that integrates each lobe over its own
    // roughness needs them so, as the split-sum and Monte-Carlo references here do).
    out["F_exact_base"] = std::move(exact_base);
    out["F_exact_coat"] = std::move(exact_coat);
  }
  const Lut lut = options.ndotv.empty()
                      ? Lut{}
                      : stored_as(preintegrate_lut(basis, options.bake), options.precision);
  if (options.metalness) {
    add_metal_rough(
        options,
        {.fresnel = fresnel_lobes,
         .fbar = [&](double ndotv,
                     double roughness) { return fbar_lobes(lut.view(), ndotv, roughness); }},
        out);
  }
  if (options.ndotv.empty()) return;
  const runtime::AnalyticLutCoefficients& analytic = runtime::shipped_analytic_lut(basis.kind);
  add_preintegrated_points(options, lut, out);
  ordered_json total = ordered_json::array(), base = ordered_json::array(),
               coat_lobe = ordered_json::array(), closed_form = ordered_json::array();
  for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
    const double ndotv = options.ndotv[i];
    const auto lobes = fbar_lobes(lut.view(), ndotv, options.roughness[i]);
    total.push_back(lobes.total());
    base.push_back(lobes.base);
    coat_lobe.push_back(lobes.coat);
    if (film) continue;
    closed_form.push_back(
        runtime::evaluate_coated_preintegrated(
            compiled.coefficients, coefficients,
            runtime::preintegrated_basis_analytic(analytic, ndotv, options.roughness[i]),
            runtime::preintegrated_basis_analytic(analytic, ndotv, coefficients.roughness), ndotv)
            .total());
  }
  out["Fbar"] = std::move(total);
  out["Fbar_base"] = std::move(base);
  out["Fbar_coat"] = std::move(coat_lobe);
  if (!film) out["Fbar_analytic"] = std::move(closed_form);
  if (options.reference) {
    const TabulatedCurve in_air_exact(*in_air);
    const TabulatedCurve under_exact(*under);
    ordered_json split_sum = ordered_json::array(), monte_carlo = ordered_json::array(),
                 standard_error = ordered_json::array();
    for (std::size_t i = 0; i < options.ndotv.size(); ++i) {
      const double ndotv = options.ndotv[i];
      split_sum.push_back(
          layered_split_sum(in_air_exact, under_exact, coat.input, ndotv, options.roughness[i]));
      const LayeredEstimate estimate =
          layered_albedo({*in_air, *metal_in_coat, coat.input, options.roughness[i]}, ndotv);
      monte_carlo.push_back(estimate.mean);
      standard_error.push_back(estimate.standard_error);
    }
    out["Fbar_reference"] = std::move(split_sum);
    out["Fbar_layered_reference"] = std::move(monte_carlo);
    out["Fbar_layered_reference_standard_error"] = std::move(standard_error);
  }
  if (options.quad) {
    const runtime::LtcTableView ltc = runtime::shipped_ltc_table();
    const auto lit = [&](double ndotv, double roughness) {
      return film ? runtime::film_polygon_light_ltc_coated(*film, coefficients, lut.view(), ltc,
                                                           ndotv, roughness, *options.quad)
                  : runtime::polygon_light_ltc_coated(compiled.coefficients, coefficients,
                                                      lut.view(), ltc, ndotv, roughness,
                                                      *options.quad);
    };
    add_coated_quad_light(options, *options.quad, compiled, lit, *in_air, *under, out);
  }
}

}  // namespace matc::evaluation
