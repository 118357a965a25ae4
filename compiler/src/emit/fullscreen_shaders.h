// Full-screen GLSL passes that put our Fresnel beside Schlick's on a device: the cost benchmark
// (bench/fullscreen_cost.cpp) and the comparison renders (examples/render). Not part of what
// `matc` writes; built from templates/glsl/{fullscreen.vert,cost_pass.frag,*_render.frag}.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "compile/compile.h"
#include "emit/build.h"
#include "spirv/shader_compiler.h"

namespace matc {

// Schlick's with a constant F0, or with F0 from a map; ours with a material's compiled
// coefficients; ours per pixel from reflectivity and edge-tint maps through the coefficient table
// (a textured metal); ours from baked coefficient textures (F0, C2, C3 maps, `matc bake`); ours per
// pixel from an F0 map on the curve's rows at F0 = 0 (a glTF metal's textured Schlick curve,
// matc_coefficients_from_f0); ours per pixel from an F0 map through an F0 table (a textured glTF
// metal under an edge colour or a coat, MATC_COEFFICIENTS_FROM_F0_TABLE; the coefficient table's
// binding stands in for it: texelFetch's code does not depend on the texture). Coated
// metals (docs/coating.md), two lobes each: ours for a coated material (its base and coat lobes);
// ours bare with a Schlick coat lobe (F0 0.04) attenuating it; Filament's clear coat (Schlick with
// F0 converted into the coat, f0ClearCoatToSurface, under the same Schlick coat lobe); ours coated
// per pixel through an F0 table (a textured glTF metal under a coat: its coefficients in air and
// under the coat from the table, MATC_UNDER_COAT_FROM_F0_TABLE too, into the coated snippet's
// textured functions). glTF's metal-rough model per pixel (a base colour map and a metalness map):
// Schlick's with F0 blended from the dielectric's 0.04 to the base colour by metalness, as engines
// shade it (one curve); ours per pixel from the base colour (matc_coefficients_from_f0) mixed by
// metalness with the dielectric's Schlick curve (matc_metal_rough), for image light with the
// engine's two-channel DFG fetch for the dielectric (matc_lut's binding stands in for it). The
// same under a clear coat: Schlick's blended F0 under a Schlick coat lobe, as three.js layers it;
// ours coated per pixel through the F0 table, mixed with the dielectric under the coat's
// transmission (matc_metal_rough_<name>).
enum class FresnelModel {
  schlick,
  schlick_textured,
  ours,
  table,
  baked,
  from_f0,
  f0_table,
  ours_coated,
  ours_with_schlick_coat,
  schlick_clear_coat,
  f0_table_coated,
  schlick_metal_rough,
  from_f0_metal_rough,
  schlick_clear_coat_metal_rough,
  f0_table_coated_metal_rough,
  // A metal under a thin film: ours from its own table (docs/thin-film.md), against Belcour and
  // Barla's 2017 evaluation over a dielectric base of index from F0, as glTF engines' iridescence
  // (the Khronos sample viewer's evalIridescence) shades it, written here from the paper.
  film_table,
  film_airy_dielectric_base,
  // A filmed metal under a coat (docs/thin-film.md, "Under a coat"): its table is the base lobe,
  // the coat lobe the coated snippet's.
  film_table_coated,
  // A thickness per pixel (docs/thin-film.md): ours from the film's stack, against the same
  // evaluation at a thickness of the range; both at a thickness coordinate that varies per pixel.
  film_stack,
  film_airy_dielectric_base_textured
};
// F alone (mu from the pixel); F inside one GGX punctual light (D, height-correlated Smith V, F,
// NdotL); image-based light: preintegrated Fbar from one table fetch times the prefiltered
// environment (one more fetch, the same in every variant); a quad area light (LTC: that fetch, one
// LTC table fetch, the polygon integral, times Fbar); the same quad light at the quality level,
// ours with the Fresnel following the light (Schlick's as in quad_light); or Fbar without a fetch:
// ours from matc_preintegrated_basis_analytic, Schlick's from Karis' mobile approximation.
enum class FresnelQuantity {
  direct,
  ggx_light,
  preintegrated,
  quad_light,
  quad_light_following,
  preintegrated_closed_form
};

// What the cost pass reads at one binding of set 0. The table is the preintegrated one (for
// Schlick's variants the ComparisonLobes bake); the material maps are F0 (Schlick's textured, and
// ours per pixel from F0), reflectivity and edge tint (the coefficient table) or F0, C2, C3
// (baked textures).
enum class CostPassResource {
  table,
  sampler,
  coefficient_table,
  ltc_table,
  material_map,
  environment,
  film_table
};
struct CostPassBinding {
  std::uint32_t binding = 0;
  CostPassResource resource = CostPassResource::table;
};
// Whether a model draws a filmed material (its table, or its film over a dielectric base).
bool draws_filmed_material(FresnelModel model);
// Whether a model draws a coated material's two lobes (ours coated, at its coefficients or per
// pixel through its F0 table): its cost pass needs a coated material.
bool draws_coated_material(FresnelModel model);
// Every binding the cost pass of (model, quantity) declares, the one place that decides them.
std::vector<CostPassBinding> cost_pass_bindings(FresnelModel model, FresnelQuantity quantity);

// One triangle covering the viewport, from gl_VertexIndex.
std::string fullscreen_vertex_source();

// The benchmarks' fragment shader: per pixel, one quantity of `compiled` with one model, reading
// what cost_pass_bindings(model, quantity) lists.
std::string cost_pass_source(const Build& build, const CompiledMaterial& compiled,
                             FresnelModel model, FresnelQuantity quantity, std::uint32_t width,
                             std::uint32_t height);

// The comparison render's fragment shader (method and samples in push constants; see the
// template for the bindings). curve_size: entries of the exact-curve buffer.
std::string comparison_render_source(const Build& build, const CompiledMaterial& compiled,
                                     std::size_t curve_size, std::uint32_t width,
                                     std::uint32_t height);

// The area-light render's fragment shader (templates/glsl/area_light_render.frag): a sphere on a
// plane under a rectangular light; the comparison render's bindings plus the LTC table at 4.
std::string area_light_render_source(const Build& build, const CompiledMaterial& compiled,
                                     std::size_t curve_size, std::uint32_t width,
                                     std::uint32_t height);

// The coated comparison render's fragment shader (templates/glsl/coated_render.frag): the
// comparison render's sphere and bindings for a coated material, both lobes, beside the engines'
// F0-in-coat Schlick (the exact-curve buffer holds the base lobe in rgb, the coat lobe in a).
// std::invalid_argument for a material without a coat.
std::string coated_render_source(const Build& build, const CompiledMaterial& compiled,
                                 std::size_t curve_size, std::uint32_t width, std::uint32_t height);

// The textured render's fragment shader (templates/glsl/textured_render.frag): a sphere whose
// reflectivity and edge tint vary per pixel, from a buffer (see the template for the bindings).
std::string textured_render_source(const Build& build, std::uint32_t width, std::uint32_t height);

// The baked-texture render's fragment shader (templates/glsl/baked_render.frag): a textured
// ground plane in perspective, F from the baked coefficient textures or from the maps' own mips.
struct PlaneCamera {
  double height = 1.0;        // above the plane
  double pitch = 0.35;        // radians down from the horizon
  double tan_half_fov = 0.5;  // vertical
  double uv_per_unit = 0.5;   // texture coordinates per unit of plane
};
std::string baked_render_source(const Build& build, const PlaneCamera& camera, std::uint32_t width,
                                std::uint32_t height);

// One of the sources above as SPIR-V: compiled (GLSL), optimised and validated for Vulkan 1.1.
SpirvWords compile_fullscreen_stage(const std::string& source, ShaderStage stage,
                                    const std::string& name);

}  // namespace matc
