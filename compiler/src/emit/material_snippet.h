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

std::string material_snippet_source(ShaderLanguage language, const CompiledMaterial& compiled,
                                    std::string_view inputs_hash);

// The values every per-material template shares: name, version, source file, hash, F0, error,
// and the coefficient rows as shader (red, green, blue) and C (red_c, ...) float lists.
TemplateValues material_template_values(const CompiledMaterial& compiled,
                                        std::string_view inputs_hash);

}  // namespace matc
