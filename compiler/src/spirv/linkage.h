// SPIR-V library modules: exporting matc's functions, importing them, linking (SPIRV-Tools).
//
// glslang 12 cannot compile a GLSL file without an entry point, so a library is compiled with a
// placeholder `void main() {}` and uncalled functions kept, then rewritten here: the entry point
// goes, the Linkage capability comes, and each exported function gets a LinkageAttributes
// decoration with its GLSL name (parameters stay as glslang passes them: Function-storage
// pointers). A consumer declares the same prototypes; import_functions() turns its placeholder
// definitions into the declarations the linker resolves.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "spirv/shader_compiler.h"

namespace matc {

// Throws std::logic_error when a named function is missing from the module.
SpirvWords export_functions(const SpirvWords& module, std::span<const std::string> functions);
SpirvWords import_functions(const SpirvWords& module, std::span<const std::string> functions);

// spvtools::Link of the modules into one complete module; throws std::runtime_error with the
// linker's messages on failure.
SpirvWords link_spirv(std::span<const SpirvWords> modules, std::string_view name);

}  // namespace matc
