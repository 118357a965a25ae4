// SPIRV-Tools on matc's modules: validation, performance optimisation, disassembly, counting.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "spirv/shader_compiler.h"

namespace matc {

enum class SpirvTarget {
  vulkan_1_1,     // a complete module to run (SPIR-V 1.3)
  universal_1_3,  // a library module: the Linkage capability is not allowed under Vulkan rules
};

// The validator's messages when `words` is not valid for `target`, or nothing.
std::optional<std::string> spirv_validation_errors(const SpirvWords& words, SpirvTarget target);
// Throws std::runtime_error with the validator's messages when `words` is not valid for `target`.
void validate_spirv(const SpirvWords& words, SpirvTarget target, std::string_view name);

// SPIRV-Tools' performance passes (inlining, constant folding, dead-code elimination, ...),
// then validation of the result. Exported functions survive.
SpirvWords optimize_spirv(const SpirvWords& words, SpirvTarget target, std::string_view name);

std::string disassemble_spirv(const SpirvWords& words);

// The number of instructions inside function bodies (between OpFunction and OpFunctionEnd,
// both excluded): the code a driver compiles, without types, names and decorations.
std::size_t count_function_instructions(const SpirvWords& words);

}  // namespace matc
