// The languages matc writes. GLSL and HLSL also compile to SPIR-V in-process (glslang); WGSL is
// written as text only and proven by Dawn in the tests (docs/shaders.md).
#pragma once

#include <string_view>

namespace matc {

enum class ShaderLanguage { glsl, hlsl, wgsl };

std::string_view shader_language_name(ShaderLanguage language);  // "glsl", "hlsl", "wgsl"

}  // namespace matc
