#include "matc/emit/validation_kernel.h"

#include "matc/emit/template.h"
#include "matc/version.h"

namespace matc {

std::string validation_kernel_source(ShaderLanguage language, std::string_view library,
                                     std::string_view material, std::string_view material_name) {
  return fill_template(
      language == ShaderLanguage::glsl ? "glsl/validate.comp" : "hlsl/validate.hlsl",
      {{"version", kVersion},
       {"name", std::string(material_name)},
       {"library", std::string(library)},
       {"material", std::string(material)}});
}

std::string table_validation_kernel_source(ShaderLanguage language, std::string_view library) {
  return fill_template(
      language == ShaderLanguage::glsl ? "glsl/validate_table.comp" : "hlsl/validate_table.hlsl",
      {{"version", kVersion}, {"library", std::string(library)}});
}

std::string area_light_validation_kernel_source(ShaderLanguage language, std::string_view library) {
  return fill_template(language == ShaderLanguage::glsl ? "glsl/validate_area_lights.comp"
                                                        : "hlsl/validate_area_lights.hlsl",
                       {{"version", kVersion}, {"library", std::string(library)}});
}

}  // namespace matc
