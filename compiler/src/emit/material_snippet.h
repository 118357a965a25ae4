// One material's shader snippet (<name>.glsl / <name>.hlsl): its coefficients as a constant
// MatcFresnelCoefficients and the functions matc_fresnel_<name> and
// matc_fresnel_preintegrated_<name>. Needs the shared library included first.
#pragma once

#include <string>
#include <string_view>

#include "compile/compile.h"
#include "emit/shader_literals.h"
#include "emit/template.h"

namespace matc {

// `per_material_build`: the build's table has a layer per basis (--basis auto); the snippet then
// calls its basis' functions (matc_fresnel_f82 for an f82 material) and has
// matc_lut_texcoord_<name>, where its layer is sampled.
std::string material_snippet_source(ShaderLanguage language, const CompiledMaterial& compiled,
                                    std::string_view inputs_hash, bool per_material_build = false);

// The suffix of the library functions of `compiled`'s basis: empty in a one-basis build and for
// the first layer, else "_" and the basis' name.
std::string basis_function_suffix(const CompiledMaterial& compiled, bool per_material_build);

// The values every per-material template shares: name, version, source file, hash, F0, error,
// and the coefficient rows as shader (red, green, blue) and C (red_c, ...) float lists.
TemplateValues material_template_values(const CompiledMaterial& compiled,
                                        std::string_view inputs_hash);

}  // namespace matc
