#include "emit/material_snippet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "base/embedded_templates.h"
#include "emit/layer_suffix.h"
#include "matc/version.h"
#include "material/parse.h"

namespace matc {

TemplateValues material_template_values(const CompiledMaterial& compiled,
                                        std::string_view inputs_hash) {
  const std::string& name = compiled.material.name;
  // Parsing already validated the name; checked again because it becomes shader identifiers.
  if (const auto problem = material_name_problem(name))
    throw std::logic_error(
        fmt::format("material name '{}' reached the emitter: {}", name, *problem));
  const auto& c = compiled.coefficients;
  const double worst = worst_channel(shader_fresnel_error(compiled).max_abs);
  return {
      {"name", name},
      {"version", kVersion},
      {"version_number", std::to_string(kVersionNumber)},
      {"source_file", comment_safe_file_name(compiled.material.source_path)},
      {"inputs_hash", std::string(inputs_hash)},
      {"f0", fmt::format("{:.4f}, {:.4f}, {:.4f}", compiled.f0[0], compiled.f0[1], compiled.f0[2])},
      {"max_error", fmt::format("{:.4f}", worst)},
      {"color_space", std::string(color_space_name(compiled.color.working_space))},
      {"red", float_list(c[0])},
      {"green", float_list(c[1])},
      {"blue", float_list(c[2])},
      {"red_c", fmt::format("{{{}}}", float_list(c[0], true))},
      {"green_c", fmt::format("{{{}}}", float_list(c[1], true))},
      {"blue_c", fmt::format("{{{}}}", float_list(c[2], true))}};
}

namespace {

// A layered snippet's template (material_coated, material_film_coated) with the coat lobe's parts
// put in: templates/<language>/coat_lobe_{constants,functions,preintegrated}, which both layered
// snippets share. js/package/stage.mjs puts them in the same way into the templates it ships.
std::string layered_snippet(ShaderLanguage language, std::string_view kind,
                            const TemplateValues& values) {
  const std::string path = template_path(language, kind);
  std::string text(embedded_templates::file(path));
  for (const std::string_view part :
       {"coat_lobe_constants", "coat_lobe_functions", "coat_lobe_preintegrated"}) {
    std::string part_text(embedded_templates::file(template_path(language, part)));
    if (part_text.ends_with('\n')) part_text.pop_back();
    const std::string placeholder = fmt::format("{{{{{}}}}}", part);
    const std::size_t at = text.find(placeholder);
    if (at == std::string::npos)
      throw std::logic_error(fmt::format("template {}: no {}", path, placeholder));
    text.replace(at, placeholder.size(), part_text);
  }
  return fill_template_text(text, values, path);
}

// What both layered snippets fill in about the coat (the shared coat_lobe_* parts' values, the
// under-coat fit and both lobes' error against the exact layered curve).
void add_coat_values(const CompiledCoat& coat, TemplateValues& values) {
  const runtime::CoatCoefficients& c = coat.coefficients;
  values["under_red"] = float_list(c.under_coat[0]);
  values["under_green"] = float_list(c.under_coat[1]);
  values["under_blue"] = float_list(c.under_coat[2]);
  values["coat"] = float_list(c.coat);
  values["coat_weight"] = float_literal(c.weight);
  values["coat_roughness"] = float_literal(c.roughness);
  values["coat_ior"] = fmt::format("{}", c.ior);
  values["coat_max_error"] = fmt::format("{:.4f}", coat.coat_max_error);
  values["layered_max_error"] = fmt::format("{:.4f}", worst_channel(coat.layered_error.max_abs));
}

// A coated material's snippet (templates/<language>/material_coated.*): the metal in air, the
// metal under the coat and the coat's own coefficients, and the layering (docs/coating.md).
std::string coated_snippet_source(ShaderLanguage language, const CompiledMaterial& compiled,
                                  TemplateValues values) {
  const CompiledCoat& coat = *compiled.coat;
  const runtime::CoatCoefficients& c = coat.coefficients;
  for (const char* unused : {"fresnel", "fresnel_preintegrated", "clamp_note", "max_error"})
    values.erase(unused);
  const double inverse_ior_squared = 1.0 / (c.ior * c.ior);
  std::array<double, 3> log2_color{};
  for (std::size_t i = 0; i < 3; ++i)
    log2_color[i] = c.color[i] >= 1.0 ? 0.0 : std::log2(std::max(c.color[i], 1e-30));
  add_coat_values(coat, values);
  const bool clear = log2_color == std::array<double, 3>{};
  const std::string tint_vector = language == ShaderLanguage::hlsl   ? "float3"
                                  : language == ShaderLanguage::wgsl ? "vec3f"
                                                                     : "vec3";
  // A clear coat tints nothing: no exponentials where the common case needs none.
  values["tint_body"] =
      clear ? fmt::format("  return {}(1.0);", tint_vector)
            : fmt::format(
                  "  {} inverse_mu_inside = {}({} + {} * mu * mu);\n  return exp2({}({}) * "
                  "inverse_mu_inside);",
                  language == ShaderLanguage::wgsl ? "let" : "float",
                  language == ShaderLanguage::hlsl   ? "rsqrt"
                  : language == ShaderLanguage::wgsl ? "inverseSqrt"
                                                     : "inversesqrt",
                  float_literal(1.0 - inverse_ior_squared), float_literal(inverse_ior_squared),
                  tint_vector, float_list(log2_color));
  // A full coat leaves nothing of the metal in air: no mix, and no in-air sum to compute.
  const std::string& name = compiled.material.name;
  values["base"] = c.weight >= 1.0 ? std::string("through")
                                   : fmt::format(
                                         "{}(matc_combine(in_air, values), through, "
                                         "matc_coat_weight_{})",
                                         language == ShaderLanguage::hlsl ? "lerp" : "mix", name);
  values["under_coat_max_error"] =
      fmt::format("{:.4f}", worst_channel(coat.under_coat_error.max_abs));
  return layered_snippet(language, "material_coated", values);
}

// A filmed metal's snippet (templates/<language>/material_film.*): its F and Fbar from its own
// table's texels (runtime/film_table.h), its coefficients kept for F0. Under a coat
// (material_film_coated.*) the table holds the base lobe, and the coat lobe is the coated
// snippet's.
std::string film_snippet_source(ShaderLanguage language, const CompiledMaterial& compiled,
                                TemplateValues values) {
  const FilmInput& film = *compiled.material.film;
  for (const char* unused : {"fresnel", "fresnel_preintegrated", "clamp_note"})
    values.erase(unused);
  values["film_ior"] = fmt::format("{}", film.ior);
  values["film_thickness"] = fmt::format("{}", film.thickness_nm);
  values["film_weight"] = fmt::format("{}", film.weight);
  if (compiled.film_stack) {
    // A thickness per pixel: the stack's slice count and range, and nanometres to its coordinate.
    const runtime::FilmStack& stack = *compiled.film_stack;
    TemplateValues stack_values{
        {"name", compiled.material.name},
        {"film_slices", fmt::format("{}", stack.slices.size())},
        {"film_minimum", fmt::format("{}", stack.minimum_nm)},
        {"film_maximum", fmt::format("{}", stack.maximum_nm)},
        {"film_minimum_float", float_literal(stack.minimum_nm)},
        {"film_maximum_float", float_literal(stack.maximum_nm)},
        {"film_stack_error", fmt::format("{:.4f}", compiled.film_stack_error)}};
    values["film_thickness"] = fmt::format("{}-{}", stack.minimum_nm, stack.maximum_nm);
    values["film_stack"] =
        fill_template(template_path(language, "film_stack_constants"), stack_values);
  }
  values["fit_max_error"] =
      fmt::format("{:.4f}", worst_channel(compiled.accuracy.decomposition.max_abs));
  if (!compiled.coat) {
    values.try_emplace("film_stack", "");
    return fill_template(template_path(language, "material_film"), values);
  }
  add_coat_values(*compiled.coat, values);
  return layered_snippet(language, "material_film_coated", values);
}

}  // namespace

std::string basis_function_suffix(const CompiledMaterial& compiled, bool per_material_build) {
  if (!per_material_build || compiled.basis == runtime::kPerMaterialBases.front()) return "";
  return layer_suffix(compiled.basis);
}

std::string material_snippet_source(ShaderLanguage language, const CompiledMaterial& compiled,
                                    std::string_view inputs_hash, bool per_material_build) {
  TemplateValues values = material_template_values(compiled, inputs_hash);
  values.erase("red_c");
  values.erase("green_c");
  values.erase("blue_c");
  if (compiled.coat && !compiled.film_table)
    return coated_snippet_source(language, compiled, std::move(values));
  // A curve matc proved non-negative needs no clamp at 0 (fit/nonnegative_curve.h).
  const bool nonnegative = compiled.fresnel_nonnegative;
  const std::string suffix = basis_function_suffix(compiled, per_material_build);
  values["fresnel"] = (nonnegative ? "matc_fresnel_sum" : "matc_fresnel") + suffix;
  values["fresnel_preintegrated"] =
      nonnegative ? "matc_fresnel_preintegrated_sum" : "matc_fresnel_preintegrated";
  values["clamp_note"] = nonnegative ? "Its curve stays above 0 (checked when compiled): no clamp."
                                     : "Clamped at 0, where the fitted curve may dip below it.";
  values["layer_texcoord"] =
      per_material_build
          ? fill_template(template_path(language, "material_layer"),
                          {{"name", compiled.material.name},
                           {"basis", std::string(runtime::basis_name(compiled.basis))},
                           {"suffix", suffix}})
          : "";
  if (compiled.film_table) return film_snippet_source(language, compiled, std::move(values));
  return fill_template(template_path(language, "material"), values);
}

}  // namespace matc
