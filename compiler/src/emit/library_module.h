// Linkable SPIR-V library modules (matc_fresnel.spv, <name>.spv): GLSL compiled with a placeholder
// entry point, the listed functions exported, validated and optimised; and the bytes of a .spv
// file.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "spirv/shader_compiler.h"

namespace matc {

SpirvWords compile_library_module(std::string glsl_source, const std::string& name,
                                  std::span<const std::string> exports);

// The words as a .spv file stores them (little-endian).
std::string spirv_file_bytes(const SpirvWords& words);

// The names a library module exports: the shared library's (with each further layer's functions,
// `further_layer_suffixes` such as "_f82", of a per-material build), and one material's.
std::vector<std::string> shared_library_exports(
    bool embedded_lut, std::span<const std::string> further_layer_suffixes = {});
// A coated material (docs/coating.md) exports its coat lobe's two functions too.
std::vector<std::string> material_library_exports(std::string_view material_name,
                                                  bool coated = false);

}  // namespace matc
