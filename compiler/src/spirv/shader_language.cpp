#include "spirv/shader_language.h"

namespace matc {

std::string_view shader_language_name(ShaderLanguage language) {
  switch (language) {
    case ShaderLanguage::hlsl:
      return "hlsl";
    case ShaderLanguage::wgsl:
      return "wgsl";
    case ShaderLanguage::glsl:
      break;
  }
  return "glsl";
}

std::optional<ShaderLanguage> shader_language_from_name(std::string_view name) {
  for (const ShaderLanguage language : kShaderLanguages)
    if (shader_language_name(language) == name) return language;
  return std::nullopt;
}

}  // namespace matc
