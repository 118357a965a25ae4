#include "emit/material_json.h"

#include <string>
#include <variant>

#include <fmt/core.h>

#include "fit/coefficients.h"
#include "matc/version.h"

namespace matc {
namespace {

using nlohmann::ordered_json;

ordered_json error_stats_json(const ErrorStats& stats) {
  return {{"max", rgb_json(stats.max_abs)}, {"rms", rgb_json(stats.rms)}};
}

ordered_json input_json(const Material& material) {
  ordered_json input;
  if (const auto* artistic = std::get_if<ArtisticInput>(&material.model)) {
    input = {{"reflectivity", rgb_json(artistic->reflectivity)},
             {"edge_tint", rgb_json(artistic->edge_tint)}};
  } else if (const auto* ior = std::get_if<IorInput>(&material.model)) {
    input = {{"n", rgb_json(ior->n)}, {"k", rgb_json(ior->k)}};
  } else if (const auto* f82 = std::get_if<F82TintInput>(&material.model)) {
    input = {{"f0", rgb_json(f82->f0)}, {"tint", rgb_json(f82->tint)}};
  } else {
    const auto& spectral = std::get<SpectralInput>(material.model);
    input = spectral.preset.empty() ? ordered_json{{"file", spectral.file}}
                                    : ordered_json{{"preset", spectral.preset}};
  }
  ordered_json out = {{std::string(model_key(material.model)), input}};
  if (material.film) {
    const FilmInput& film = *material.film;
    out["film"] = {{"weight", film.weight}, {"ior", film.ior}, {"thickness", film.thickness_nm}};
    if (film.thickness_minimum_nm) {
      out["film"]["thickness"] = {{"minimum", *film.thickness_minimum_nm},
                                  {"maximum", film.thickness_nm}};
    }
  }
  return out;
}

// A coated material's coat (docs/coating.md): what was asked, what was fitted, how close.
ordered_json coat_json(const CompiledCoat& coat) {
  const runtime::CoatCoefficients& c = coat.coefficients;
  return {{"input",
           {{"weight", coat.input.weight},
            {"ior", coat.input.ior},
            {"roughness", coat.input.roughness},
            {"color", rgb_json(coat.input.color)}}},
          {"under_coat_coefficients", coefficient_rows_json(c.under_coat)},
          {"coat_coefficients", {c.coat[0], c.coat[1], c.coat[2], c.coat[3]}},
          {"layered", {{"F0", rgb_json(coat.layered_f0)}, {"F82", rgb_json(coat.layered_f82)}}},
          {"accuracy",
           {{"metric",
             "absolute error vs the exact layered reflectance (smooth interfaces) over mu = "
             "cos(theta) uniform in [0, 1]"},
            {"layered", error_stats_json(coat.layered_error)},
            {"under_coat", error_stats_json(coat.under_coat_error)},
            {"coat_max", coat.coat_max_error}}}};
}

// A filmed metal's tables (runtime/film_table.h): what its shader functions read for F and Fbar.
ordered_json film_table_json(const runtime::FilmTable& table) {
  ordered_json fresnel = ordered_json::array(), preintegrated = ordered_json::array();
  for (const Rgb& node : table.fresnel)
    fresnel.push_back(rgb_json(node));
  for (const Rgb& node : table.preintegrated)
    preintegrated.push_back(rgb_json(node));
  // The layout's numbers come from the table's constants, so the text cannot fall behind them.
  using runtime::FilmTable;
  return {{"layout",
           fmt::format("fresnel: F at mu = (i / {})^2; preintegrated: Fbar at NdotV = (i / {})^2 "
                       "and roughness {} + {} (j / {})^2, entry {} j + i; read linearly and "
                       "bilinearly between nodes, as the shaders do",
                       FilmTable::kCosineNodes - 1, FilmTable::kViewNodes - 1,
                       FilmTable::kMinRoughness, 1.0 - FilmTable::kMinRoughness,
                       FilmTable::kRoughnessNodes - 1, FilmTable::kViewNodes)},
          {"fresnel", std::move(fresnel)},
          {"preintegrated", std::move(preintegrated)}};
}

}  // namespace

ordered_json rgb_json(const Rgb& rgb) {
  return ordered_json::array({rgb[0], rgb[1], rgb[2]});
}

ordered_json coefficient_rows_json(const runtime::Coefficients& coefficients) {
  ordered_json rows = ordered_json::array();
  for (const auto& channel : coefficients)
    rows.push_back({channel[0], channel[1], channel[2], channel[3]});
  return rows;
}

ordered_json compiled_material_json(const CompiledMaterial& compiled,
                                    const runtime::BasisView& basis, bool per_material_build) {
  const Material& material = compiled.material;
  ordered_json out;
  out["matc_version"] = kVersion;
  out["name"] = material.name;
  // The file name only, so the output does not depend on where the build ran.
  out["source"] = std::filesystem::path(material.source_path).filename().generic_string();
  out["input"] = input_json(material);
  out["roughness"] = material.roughness ? ordered_json(*material.roughness) : ordered_json();

  ordered_json resolved;
  if (compiled.ior) {
    const auto& ior = *compiled.ior;
    const auto& artistic = *compiled.artistic;
    resolved["ior"] = {{"n", rgb_json({ior[0].n, ior[1].n, ior[2].n})},
                       {"k", rgb_json({ior[0].k, ior[1].k, ior[2].k})}};
    resolved["artistic"] = {
        {"reflectivity",
         rgb_json({artistic[0].reflectivity, artistic[1].reflectivity, artistic[2].reflectivity})},
        {"edge_tint",
         rgb_json({artistic[0].edge_tint, artistic[1].edge_tint, artistic[2].edge_tint})}};
  } else if (const auto* spectral = std::get_if<SpectralInput>(&material.model)) {
    const auto& spectrum = spectral->spectrum;
    resolved["spectral"] = {
        {"data_range_nm", {spectrum.wavelength_nm.front(), spectrum.wavelength_nm.back()}},
        {"data_samples", spectrum.wavelength_nm.size()},
        {"integration",
         fmt::format("CIE 1931 2-degree observer x D65, 360-830 nm at 1 nm, Bradford-adapted to "
                     "{}, normalised so a perfect mirror is (1, 1, 1)",
                     color_space_name(compiled.color.working_space))}};
  }
  ordered_json color = {
      {"working_space", color_space_name(compiled.color.working_space)},
      {"input_space", std::holds_alternative<SpectralInput>(material.model)
                          ? ordered_json("spectral")
                          : ordered_json(color_space_name(
                                input_color_space(material, compiled.color.working_space)))},
      {"range", {{"min", rgb_json(compiled.range.min)}, {"max", rgb_json(compiled.range.max)}}},
      {"within_unit_range", compiled.range.within_unit_range()},
      {"gamut_mapping", gamut_mapping_name(compiled.color.gamut_mapping)},
      {"saturation_kept", compiled.saturation}};
  out["color"] = std::move(color);
  resolved["F0"] = rgb_json(compiled.f0);
  resolved["F82"] = rgb_json(compiled.f82);
  out["resolved"] = resolved;

  ordered_json basis_json = {{"name", runtime::basis_name(basis.kind)},
                             {"samples", basis.samples()}};
  if (basis.kind == runtime::BasisKind::paper) {
    basis_json["solve"] = "probes";
    basis_json["probes_mu"] = {basis.probe_mu(0), basis.probe_mu(1)};
  } else {
    basis_json["solve"] = "minimax";
    basis_json["minimax_cosines"] = kMinimaxCosines;
  }
  // Where its bbar is in the table (layers side by side, matc_lut.*.json).
  if (per_material_build) basis_json["lut_layer"] = runtime::per_material_layer(basis.kind);
  out["basis"] = std::move(basis_json);
  out["coefficients"] = coefficient_rows_json(compiled.coefficients);
  out["energy_compensation"] = {{"F_avg", rgb_json(compiled.average_fresnel)}};
  out["accuracy"] = {{"samples", compiled.accuracy.samples},
                     {"metric",
                      "absolute error vs the exact Fresnel curve over mu = cos(theta) "
                      "uniform in [0, 1]"},
                     {"decomposition", error_stats_json(compiled.accuracy.decomposition)},
                     {"schlick", error_stats_json(compiled.accuracy.schlick)},
                     {"f82_tint", error_stats_json(compiled.accuracy.f82_tint)}};
  if (compiled.coat) out["coat"] = coat_json(*compiled.coat);
  if (compiled.film_table) {
    out["accuracy"]["film_table"] = error_stats_json(compiled.film_table_error);
    out["film_table"] = film_table_json(*compiled.film_table);
  }
  if (compiled.film_stack) {
    const runtime::FilmStack& stack = *compiled.film_stack;
    out["accuracy"]["film_stack_thickness"] = compiled.film_stack_error;
    out["film_stack"] = {
        {"layout",
         fmt::format(
             "a thickness per pixel: {0} x {1} texels, {2} slices of films uniform over the "
             "range; rows 0 to {3}: F of each slice; row {2} + {2} j + s: Fbar of slice s "
             "at roughness node j (docs/thin-film.md); film_table is the last slice, the "
             "film at the maximum",
             runtime::FilmTable::kWidth, runtime::film_stack_height(stack), stack.slices.size(),
             stack.slices.size() - 1)},
        {"slices", stack.slices.size()},
        {"size", {runtime::FilmTable::kWidth, runtime::film_stack_height(stack)}},
        {"thickness_nm", {stack.minimum_nm, stack.maximum_nm}}};
  }
  return out;
}

}  // namespace matc
