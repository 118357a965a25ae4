// GLSL and HLSL to SPIR-V, in-process with glslang (Vulkan rules, SPIR-V 1.3). WGSL is not
// compiled here: the tests run it on Dawn.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "spirv/shader_language.h"

namespace matc {

using SpirvWords = std::vector<std::uint32_t>;

// A generated shader failed to compile: a bug in matc. what() names the source and shows the
// offending generated lines with two lines of context each, not the whole shader.
class ShaderCompileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Generated kernels are compute shaders; renders and benchmarks add a full-screen vertex and
// fragment pair.
enum class ShaderStage { compute, vertex, fragment };

struct ShaderSource {
  ShaderLanguage language = ShaderLanguage::glsl;
  std::string text;  // GLSL must start with #version; HLSL has none
  std::string name;  // for diagnostics, e.g. "gold.validate.glsl"
  std::string entry_point = "main";
  // Keep functions nothing calls (library modules export them).
  bool keep_uncalled_functions = false;
  ShaderStage stage = ShaderStage::compute;
};

// Compiles one shader stage. Thread-safe: calls on different threads run concurrently.
SpirvWords compile_to_spirv(const ShaderSource& source);

// The error message for glslang's info log `log` about `source`: each "ERROR: <n>:<line>:" entry
// followed by that line of the source with its neighbours.
std::string describe_compile_errors(std::string_view log, std::string_view source,
                                    std::string_view name);

}  // namespace matc
