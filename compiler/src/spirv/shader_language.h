// The languages matc writes. GLSL and HLSL also compile to SPIR-V in-process (glslang); WGSL is
// written as text only and proven by Dawn in the tests (docs/shaders.md).
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace matc {

enum class ShaderLanguage { glsl, hlsl, wgsl };

// Every language, in the order their files are written.
inline constexpr std::array<ShaderLanguage, 3> kShaderLanguages = {
    ShaderLanguage::glsl, ShaderLanguage::hlsl, ShaderLanguage::wgsl};

std::string_view shader_language_name(ShaderLanguage language);  // "glsl", "hlsl", "wgsl"
// The language `name` names, or nullopt.
std::optional<ShaderLanguage> shader_language_from_name(std::string_view name);

}  // namespace matc
