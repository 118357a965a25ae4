#include "emit/fullscreen_shaders.h"

#include <array>
#include <stdexcept>

#include <fmt/core.h>

#include "emit/material_snippet.h"
#include "emit/template.h"
#include "matc/version.h"
#include "optics/coat.h"
#include "spirv/spirv_tools.h"

namespace matc {
namespace {

std::string f0_list(const CompiledMaterial& compiled) {
  return float_list(std::span<const double>(compiled.f0.data(), compiled.f0.size()));
}

}  // namespace

std::string fullscreen_vertex_source() {
  return fill_template("glsl/fullscreen.vert", {{"version", kVersion}});
}

namespace {

// How many material maps a model reads (bindings 4, 5, 6 of the cost pass).
int material_map_count(FresnelModel model) {
  switch (model) {
    case FresnelModel::schlick_textured:
    case FresnelModel::from_f0:
    case FresnelModel::f0_table:
    case FresnelModel::f0_table_coated:
      return 1;
    case FresnelModel::table:
    case FresnelModel::schlick_metal_rough:
    case FresnelModel::from_f0_metal_rough:
    case FresnelModel::schlick_clear_coat_metal_rough:
    case FresnelModel::f0_table_coated_metal_rough:
      return 2;
    case FresnelModel::baked:
      return 3;
    case FresnelModel::schlick:
    case FresnelModel::ours:
    case FresnelModel::ours_coated:
    case FresnelModel::ours_with_schlick_coat:
    case FresnelModel::schlick_clear_coat:
    case FresnelModel::film_table:
    case FresnelModel::film_airy_dielectric_base:
    case FresnelModel::film_table_coated:
    case FresnelModel::film_stack:
    case FresnelModel::film_airy_dielectric_base_textured:
      break;
  }
  return 0;
}

// Whether a model reads a textured metal's F0 table (bare, or in air and under a coat).
bool reads_f0_table(FresnelModel model) {
  return model == FresnelModel::f0_table || model == FresnelModel::f0_table_coated ||
         model == FresnelModel::f0_table_coated_metal_rough;
}

}  // namespace

bool draws_filmed_material(FresnelModel model) {
  return model == FresnelModel::film_table || model == FresnelModel::film_airy_dielectric_base ||
         model == FresnelModel::film_table_coated || model == FresnelModel::film_stack ||
         model == FresnelModel::film_airy_dielectric_base_textured;
}

bool draws_coated_material(FresnelModel model) {
  return model == FresnelModel::ours_coated || model == FresnelModel::f0_table_coated ||
         model == FresnelModel::f0_table_coated_metal_rough ||
         model == FresnelModel::film_table_coated;
}

std::vector<CostPassBinding> cost_pass_bindings(FresnelModel model, FresnelQuantity quantity) {
  std::vector<CostPassBinding> bindings = {{0, CostPassResource::table},
                                           {1, CostPassResource::sampler}};
  if (model == FresnelModel::table || reads_f0_table(model))
    bindings.push_back({2, CostPassResource::coefficient_table});
  if (quantity == FresnelQuantity::quad_light || quantity == FresnelQuantity::quad_light_following)
    bindings.push_back({3, CostPassResource::ltc_table});
  for (int map = 0; map < material_map_count(model); ++map)
    bindings.push_back({4 + static_cast<std::uint32_t>(map), CostPassResource::material_map});
  if (quantity == FresnelQuantity::preintegrated)
    bindings.push_back({7, CostPassResource::environment});
  if (model == FresnelModel::film_table || model == FresnelModel::film_table_coated ||
      model == FresnelModel::film_stack)
    bindings.push_back({8, CostPassResource::film_table});
  return bindings;
}

std::string cost_pass_source(const Build& build, const CompiledMaterial& compiled,
                             FresnelModel model, FresnelQuantity quantity, std::uint32_t width,
                             std::uint32_t height) {
  const bool schlick = model == FresnelModel::schlick || model == FresnelModel::schlick_textured ||
                       model == FresnelModel::schlick_clear_coat ||
                       model == FresnelModel::schlick_metal_rough ||
                       model == FresnelModel::schlick_clear_coat_metal_rough;
  const bool metal_rough = model == FresnelModel::schlick_metal_rough ||
                           model == FresnelModel::from_f0_metal_rough ||
                           model == FresnelModel::schlick_clear_coat_metal_rough ||
                           model == FresnelModel::f0_table_coated_metal_rough;
  const bool from_f0 = model == FresnelModel::from_f0 || model == FresnelModel::from_f0_metal_rough;
  // 0: no coat; 1: ours coated; 2: ours bare under a Schlick coat; 3: Filament's clear coat.
  int coat = 0;
  if (draws_coated_material(model)) coat = 1;
  if (model == FresnelModel::ours_with_schlick_coat) coat = 2;
  if (model == FresnelModel::schlick_clear_coat ||
      model == FresnelModel::schlick_clear_coat_metal_rough)
    coat = 3;
  if (coat == 1 && !compiled.coat)
    throw std::invalid_argument("cost pass: a coated model needs a coated material");
  // 0: no film; 1: ours from the film's table; 2: the Airy sum over a dielectric base; 3 and 4
  // the same with a thickness per pixel (ours from the film's stack).
  int film = 0;
  if (model == FresnelModel::film_table || model == FresnelModel::film_table_coated) film = 1;
  if (model == FresnelModel::film_airy_dielectric_base) film = 2;
  if (model == FresnelModel::film_stack) film = 3;
  if (model == FresnelModel::film_airy_dielectric_base_textured) film = 4;
  if (film == 1 && !compiled.film_table)
    throw std::invalid_argument("cost pass: the film-table model needs a filmed material");
  if ((film == 3 || film == 4) && !compiled.film_stack)
    throw std::invalid_argument("cost pass: a thickness per pixel needs a film's stack");
  if (film != 0 && quantity != FresnelQuantity::ggx_light &&
      quantity != FresnelQuantity::preintegrated && quantity != FresnelQuantity::quad_light)
    throw std::invalid_argument(
        "cost pass: a film is costed in a GGX light, image light and a quad light");
  // The coat lobe's roughness and weight: the coated material's, else a lacquer's 0.1 and 1.
  const double coat_roughness = compiled.coat ? compiled.coat->input.roughness : 0.1;
  const double coat_weight = compiled.coat ? compiled.coat->input.weight : 1.0;
  const char* model_name = "ours";
  if (model == FresnelModel::schlick) model_name = "Schlick's";
  if (model == FresnelModel::schlick_textured) model_name = "Schlick's, F0 from a map";
  if (model == FresnelModel::table) model_name = "ours from the coefficient table";
  if (model == FresnelModel::baked) model_name = "ours from baked coefficient textures";
  if (model == FresnelModel::from_f0) model_name = "ours per pixel from an F0 map";
  if (model == FresnelModel::f0_table) model_name = "ours per pixel from an F0 map and F0 table";
  if (model == FresnelModel::ours_coated) model_name = "ours, coated (two lobes)";
  if (model == FresnelModel::f0_table_coated)
    model_name = "ours, coated, per pixel from an F0 map and F0 table";
  if (model == FresnelModel::ours_with_schlick_coat) model_name = "ours under a Schlick coat lobe";
  if (model == FresnelModel::film_table_coated)
    model_name = "ours, a filmed metal under a coat (its table and the coat lobe)";
  if (model == FresnelModel::schlick_clear_coat) model_name = "Filament's clear coat (Schlick)";
  if (model == FresnelModel::schlick_metal_rough)
    model_name = "Schlick's metal-rough, F0 blended by a metalness map";
  if (model == FresnelModel::from_f0_metal_rough)
    model_name = "ours per pixel from an F0 map, mixed with the dielectric by a metalness map";
  if (model == FresnelModel::schlick_clear_coat_metal_rough)
    model_name = "Schlick's metal-rough under a Schlick clear coat lobe";
  if (model == FresnelModel::f0_table_coated_metal_rough)
    model_name =
        "ours, coated, per pixel through an F0 table, mixed with the dielectric under the coat";
  if (model == FresnelModel::film_table) model_name = "ours, filmed, from the film's table";
  if (model == FresnelModel::film_airy_dielectric_base)
    model_name = "a film's Airy sum over a dielectric base (glTF engines' iridescence)";
  if (model == FresnelModel::film_stack)
    model_name = "ours, filmed, a thickness per pixel from the film's stack";
  if (model == FresnelModel::film_airy_dielectric_base_textured)
    model_name = "a film's Airy sum over a dielectric base at a thickness per pixel";
  const char* quantity_name = "Fbar";
  if (quantity == FresnelQuantity::direct) quantity_name = "F";
  if (quantity == FresnelQuantity::ggx_light) quantity_name = "one GGX light";
  if (quantity == FresnelQuantity::quad_light) quantity_name = "quad light (LTC)";
  if (quantity == FresnelQuantity::quad_light_following)
    quantity_name = "quad light (LTC), shape and Fresnel following the light";
  if (quantity == FresnelQuantity::preintegrated_closed_form) quantity_name = "Fbar in closed form";
  const auto flag = [](bool value) { return value ? 1 : 0; };
  return fill_template(
      "glsl/cost_pass.frag",
      {{"version", kVersion},
       {"variant", fmt::format("{} {}", model_name, quantity_name)},
       {"defines",
        fmt::format(
            "#define MATC_COST_SCHLICK {}\n#define MATC_COST_TABLE {}\n#define "
            "MATC_COST_BAKED {}\n#define MATC_COST_FROM_F0 {}\n#define MATC_COST_F0_TABLE "
            "{}\n#define MATC_COST_MAPS "
            "{}\n#define MATC_COST_DIRECT "
            "{}\n#define MATC_COST_GGX_LIGHT {}\n#define MATC_COST_QUAD_LIGHT {}\n#define "
            "MATC_COST_QUAD_LIGHT_FOLLOWING {}\n#define MATC_COST_CLOSED_FORM {}\n#define "
            "MATC_COST_IMAGE_LIGHT {}\n#define MATC_COST_COAT {}\n#define "
            "MATC_COST_METAL_ROUGH {}\n#define MATC_COST_FILM {}",
            flag(schlick), flag(model == FresnelModel::table), flag(model == FresnelModel::baked),
            flag(from_f0), flag(reads_f0_table(model)), material_map_count(model),
            flag(quantity == FresnelQuantity::direct), flag(quantity == FresnelQuantity::ggx_light),
            flag(quantity == FresnelQuantity::quad_light),
            flag(quantity == FresnelQuantity::quad_light_following),
            flag(quantity == FresnelQuantity::preintegrated_closed_form),
            flag(quantity == FresnelQuantity::preintegrated), coat, flag(metal_rough), film)},
       {"library", build.library_source(ShaderLanguage::glsl)},
       {"material", build.material_source(ShaderLanguage::glsl, compiled)},
       {"name", compiled.material.name},
       // Its basis' layer of the table, as the validation kernel samples it.
       {"lut_texcoord",
        "matc_lut_texcoord" + basis_function_suffix(compiled, build.options().per_material_basis)},
       {"f0", f0_list(compiled)},
       {"coat_roughness", float_literal(coat_roughness)},
       {"coat_weight", float_literal(coat_weight)},
       {"film_ior", float_literal(compiled.material.film ? compiled.material.film->ior : 1.5)},
       {"film_thickness",
        float_literal(compiled.material.film ? compiled.material.film->thickness_nm : 0.0)},
       {"film_minimum", float_literal(compiled.material.film
                                          ? compiled.material.film->thickness_minimum_nm.value_or(
                                                compiled.material.film->thickness_nm)
                                          : 0.0)},
       {"film_weight",
        float_literal(compiled.material.film ? compiled.material.film->weight : 0.0)},
       {"width", std::to_string(width)},
       {"height", std::to_string(height)}});
}

namespace {

// A render of one material against its exact curve (comparison_render.frag,
// area_light_render.frag and coated_render.frag take the same placeholders, and `extra`).
std::string material_render_source(std::string_view template_name, const Build& build,
                                   const CompiledMaterial& compiled, std::size_t curve_size,
                                   std::uint32_t width, std::uint32_t height,
                                   TemplateValues extra = {}) {
  extra.insert({{"version", kVersion},
                {"render_sampling", fill_template("glsl/render_sampling.glsl", {})},
                {"library", build.library_source(ShaderLanguage::glsl)},
                {"material", build.material_source(ShaderLanguage::glsl, compiled)},
                {"name", compiled.material.name},
                {"f0", f0_list(compiled)},
                {"curve_size", std::to_string(curve_size)},
                {"width", std::to_string(width)},
                {"height", std::to_string(height)}});
  return fill_template(template_name, extra);
}

}  // namespace

std::string comparison_render_source(const Build& build, const CompiledMaterial& compiled,
                                     std::size_t curve_size, std::uint32_t width,
                                     std::uint32_t height) {
  // A filmed metal's Fbar is its own table's (bound at 4).
  return material_render_source(
      "glsl/comparison_render.frag", build, compiled, curve_size, width, height,
      {{"film", fmt::format("#define MATC_RENDER_FILM {}", compiled.film_table ? 1 : 0)}});
}

std::string area_light_render_source(const Build& build, const CompiledMaterial& compiled,
                                     std::size_t curve_size, std::uint32_t width,
                                     std::uint32_t height) {
  // A filmed metal's Fbar is its own table's (bound at 5, after the LTC table).
  return material_render_source(
      "glsl/area_light_render.frag", build, compiled, curve_size, width, height,
      {{"film", fmt::format("#define MATC_RENDER_FILM {}", compiled.film_table ? 1 : 0)}});
}

std::string coated_render_source(const Build& build, const CompiledMaterial& compiled,
                                 std::size_t curve_size, std::uint32_t width,
                                 std::uint32_t height) {
  if (!compiled.coat) {
    throw std::invalid_argument(compiled.material.name +
                                " has no coat: the comparison render (matc_render) draws it");
  }
  std::array<double, 3> f0_in_coat{};
  for (std::size_t c = 0; c < 3; ++c)
    f0_in_coat[c] = f0_seen_from_coat(compiled.f0[c], compiled.coat->input.ior);
  return material_render_source("glsl/coated_render.frag", build, compiled, curve_size, width,
                                height, {{"f0_in_coat", float_list(f0_in_coat)}});
}

std::string textured_render_source(const Build& build, std::uint32_t width, std::uint32_t height) {
  return fill_template("glsl/textured_render.frag",
                       {{"version", kVersion},
                        {"render_sampling", fill_template("glsl/render_sampling.glsl", {})},
                        {"library", build.library_source(ShaderLanguage::glsl)},
                        {"width", std::to_string(width)},
                        {"height", std::to_string(height)}});
}

std::string baked_render_source(const Build& build, const PlaneCamera& camera, std::uint32_t width,
                                std::uint32_t height) {
  const auto literal = [](double value) { return fmt::format("{:.9f}", value); };
  return fill_template("glsl/baked_render.frag",
                       {{"version", kVersion},
                        {"library", build.library_source(ShaderLanguage::glsl)},
                        {"width", std::to_string(width)},
                        {"height", std::to_string(height)},
                        {"camera_height", literal(camera.height)},
                        {"pitch", literal(camera.pitch)},
                        {"tan_half_fov", literal(camera.tan_half_fov)},
                        {"uv_per_unit", literal(camera.uv_per_unit)}});
}

SpirvWords compile_fullscreen_stage(const std::string& source, ShaderStage stage,
                                    const std::string& name) {
  return optimize_spirv(
      compile_to_spirv({ShaderLanguage::glsl, source, name, "main", false, stage}),
      SpirvTarget::vulkan_1_1, name);
}

}  // namespace matc
