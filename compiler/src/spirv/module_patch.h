// Rewriting a compiled SPIR-V module instead of compiling again. A material's library module
// differs from another material's only in its name (in OpName and LinkageAttributes strings) and
// its twelve coefficients (float OpConstants), so one module compiled with placeholders serves
// every material (docs/performance.md, "Per-material actions").
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "spirv/shader_compiler.h"

namespace matc {

struct ModulePatch {
  std::string from_name;  // replaced by to_name inside every OpName and LinkageAttributes string
  std::string to_name;
  // Each 32-bit float OpConstant whose value is .first gets the value .second. Every .first must
  // occur exactly once in the module (distinct placeholders, not merged with other constants).
  std::vector<std::pair<float, float>> constants;
};

// Throws std::logic_error when a placeholder is missing or repeated.
SpirvWords patch_module(const SpirvWords& module, const ModulePatch& patch);

}  // namespace matc
