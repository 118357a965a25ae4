// The compute kernels the device checks (validate/device_check.h) run: one material's generated
// code, the coefficient-table path and the area-light functions, each from a build's shared
// library in GLSL or HLSL. Every kernel runs 64 invocations per group, one query each, and binds
// 0 its queries, 1 its results, 2 the preintegrated table, 3 the sampler, and where it samples
// them 4 the coefficient table and 5 the LTC table.
//
// The material kernel (templates/*/validate.*): queries vec4 (mu, NdotV, roughness, -); results
// four vec4 per query: F, Fbar through the sampler, Fbar from the embedded table or zero, Fbar
// from the closed form.
#pragma once

#include <array>

#include "matc/runtime/vec3.h"

#include <string>
#include <string_view>

#include "compile/compile.h"
#include "emit/build.h"
#include "emit/shader_literals.h"
#include "spirv/shader_compiler.h"

namespace matc {

inline constexpr std::size_t kValidationGroupSize = 64;
inline constexpr std::size_t kValidationResultsPerQuery = 4;

// `library` and `material` are the sources of matc_fresnel.* and <name>.* in `language`. A coated
// material's kernel (templates/*/validate_coated.*) writes the base lobe in .xyz and the coat
// lobe in .w of the same four results, the coat's preintegrated F sampled at its roughness, then
// a fifth: kLayeredValidationQuad's light on both lobes (the LTC table at binding 5), and a sixth:
// glTF's metal-rough mix under the coat (matc_metal_rough_<name>) with the coat's transmission.
inline constexpr std::size_t kCoatedValidationResultsPerQuery = 6;
// A filmed material's kernel (templates/*/validate_film.*) writes three: F and Fbar, both from the
// film's tables, and kLayeredValidationQuad's light (the LTC table at binding 5).
inline constexpr std::size_t kFilmValidationResultsPerQuery = 3;
// A filmed metal under a coat (templates/*/validate_film_coated.*) writes four: F and Fbar, the
// base lobe from the film's table in .xyz and the coat lobe in .w, kLayeredValidationQuad's light
// on both lobes, and the metal-rough mix under the coat with the coat's transmission (.w).
inline constexpr std::size_t kFilmCoatedValidationResultsPerQuery = 4;
// A quad light in the shading frame (normal +z, view in the xz-plane towards +x, shading point
// at the origin), on the reflection's side and tilted: the coated and filmed kernels' light.
inline constexpr std::array<runtime::Vec3, 4> kLayeredValidationQuad = {
    {{-0.5, -1.0, 1.5}, {-2.0, -1.0, 0.5}, {-2.0, 1.0, 0.5}, {-0.5, 1.0, 1.5}}};
// The kind of kernel a material's check runs.
// film_stack: a thickness per pixel (the filmed kernel, each query's w the thickness coordinate).
enum class MaterialKernel { bare, coated, filmed, film_stack, film_coated };
MaterialKernel material_kernel_of(const CompiledMaterial& compiled);

std::string validation_kernel_source(ShaderLanguage language, std::string_view library,
                                     std::string_view material, std::string_view material_name,
                                     MaterialKernel kind = MaterialKernel::bare,
                                     std::string_view basis_suffix = "");

// The coefficient-table path's kernel (templates/*/validate_table.*): bindings 0 queries (four vec4
// each: r.rgb and mu, g.rgb and NdotV, n.rgb and roughness, k.rgb), 1 results (eight vec4: F and
// Fbar from (r, g), F from (n, k), F from baked coefficients, F per pixel from F0 = r on rows at
// F0 = 0, F from an F0 table at F0 = r in air and under a coat, the metal-rough mix of the (r, g)
// metal with a dielectric of F0 0.08 g and F90 NdotV by metalness = roughness), 2 the
// preintegrated table, 3 the
// sampler of both tables, 4 the coefficient table (its .xy).
inline constexpr std::size_t kTableValidationQueryVectors = 4;
inline constexpr std::size_t kTableValidationResultsPerQuery = 8;
std::string table_validation_kernel_source(ShaderLanguage language, std::string_view library);

// The area-light kernel (templates/*/validate_area_lights.*): bindings 0 queries (eight vec4 each:
// r.rgb and NdotV, g.rgb and roughness, N and the kind (0 quad, 1 disk, 2 sphere), V and a disk's
// or sphere's radius, a quad's corners, a disk's centre and normal or a sphere's centre),
// 1 results (one vec4: radiance.rgb, I_ltc), 2 the preintegrated table, 3 the sampler, 4 the
// coefficient table, 5 the LTC table.
inline constexpr std::size_t kAreaLightQueryVectors = 8;
std::string area_light_validation_kernel_source(ShaderLanguage language, std::string_view library);

// The kernels compiled from `build`'s library, validated and optimised for Vulkan 1.1.
SpirvWords material_validation_module(const Build& build, ShaderLanguage language,
                                      const CompiledMaterial& compiled);
SpirvWords table_validation_module(const Build& build, ShaderLanguage language);
SpirvWords area_light_validation_module(const Build& build, ShaderLanguage language);

}  // namespace matc
