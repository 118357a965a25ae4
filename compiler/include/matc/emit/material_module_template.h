// Every material's SPIR-V library module (<name>.spv, and the words in <name>.h) from one module
// compiled with placeholder coefficients and a placeholder name: a material's module is that one
// with its name and twelve coefficients patched in (spirv/module_patch.h), no glslang compile.
// The templates are checked in per basis as src/emit/material_module_templates.cpp, regenerated
// by `matc basis material-modules` (a test keeps them current). They hold for the default table
// size (MATC_LUT_SIZE enters the module) without an embedded table; other builds compile.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "matc/compile.h"
#include "matc/runtime/basis.h"
#include "matc/spirv/shader_compiler.h"

namespace matc {

inline constexpr std::string_view kTemplateMaterialName = "MATC_TEMPLATE_MATERIAL";

// The placeholder coefficients, red, green, blue rows of c_0..c_3: distinct floats that no other
// constant of the module has.
std::array<float, 12> material_module_placeholders();

// The placeholder material whose module is the template: its functions clamp at 0, or (for
// materials whose curve matc proved non-negative) not.
CompiledMaterial template_material(bool fresnel_nonnegative = false);

// The checked-in template of a basis and clamp (empty in a bootstrap build, and for a
// combination no material can have: the fitted bases always clamp).
std::span<const std::uint32_t> checked_in_material_module_template(runtime::BasisKind basis,
                                                                   bool fresnel_nonnegative);

// `compiled`'s module from a template.
SpirvWords patch_material_module(std::span<const std::uint32_t> template_words,
                                 const CompiledMaterial& compiled);

struct MaterialModuleTemplate {
  runtime::BasisKind basis = runtime::kDefaultBasis;
  bool fresnel_nonnegative = false;
  SpirvWords words;
};
// Compiles the templates of every shipped basis, clamped, and of the powers basis unclamped
// (glslang): what the checked-in file must hold.
std::vector<MaterialModuleTemplate> compile_material_module_templates();
// The C++ source of src/emit/material_module_templates.cpp.
std::string material_module_templates_source(std::span<const MaterialModuleTemplate> templates);

}  // namespace matc
