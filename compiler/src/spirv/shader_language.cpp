#include "matc/spirv/shader_language.h"

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

}  // namespace matc
