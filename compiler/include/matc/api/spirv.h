// SPIR-V for an engine that links a material's library module (<name>.spv, the header's
// matc_spirv_<name>) into its own shaders: the engine's shader compiled in-process (glslang,
// Vulkan rules, SPIR-V 1.3), the functions it takes from the material turned into imports, and the
// modules linked and validated (SPIRV-Tools). docs/api.md shows the whole path. Native builds.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace matc::api {

using SpirvWords = std::vector<std::uint32_t>;

// `language` "glsl" (the text starts with #version) or "hlsl"; `stage` "compute", "vertex" or
// "fragment"; entry point main. Another name throws std::invalid_argument; a shader that does not
// compile throws std::runtime_error with its errors, each shown at its line of `source` (`name`
// labels them).
SpirvWords compile_shader(std::string_view language, std::string_view source, std::string_view name,
                          std::string_view stage = "compute");

// The module with each named function's definition turned into a declaration that the linker
// resolves from another module (the engine declares matc's functions with placeholder bodies).
// A module that is not valid SPIR-V, or a name it does not define, throws std::invalid_argument.
SpirvWords import_functions(const SpirvWords& module, std::span<const std::string> functions);

// The modules linked into one, validated as a complete Vulkan 1.1 module. Each module is validated
// first (std::invalid_argument with the validator's messages); a link or a result that fails
// throws std::runtime_error with the linker's or the validator's messages, labelled with `name`.
SpirvWords link_spirv(std::span<const SpirvWords> modules, std::string_view name);

}  // namespace matc::api
