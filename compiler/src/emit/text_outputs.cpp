#include "emit/text_outputs.h"

#include <algorithm>
#include <variant>

#include <fmt/format.h>

#include "base/content_hash.h"
#include "base/json_format.h"
#include "emit/material_json.h"
#include "emit/material_snippet.h"
#include "emit/shader_library.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/shader_basis.h"

namespace matc {
namespace {

std::string options_key_of(const BuildOptions& options) {
  return fmt::format(
      "lut {}x{} samples {} {} {} embed {} basis {}", options.lut.size, options.lut.size,
      options.lut.samples, lut_format_name(options.lut_format),
      lut_precision_name(options.lut_precision), options.embedded_lut_size,
      options.per_material_basis ? std::string_view("auto") : runtime::basis_name(options.basis));
}

}  // namespace

TextOutputs::TextOutputs(const BuildOptions& options, std::size_t coefficient_table_size,
                         std::span<const Lut> embedded_luts)
    : per_material_(options.per_material_basis),
      options_key_(options_key_of(options)),
      color_key_(fmt::format("color {} gamut {}", color_space_name(options.color.working_space),
                             gamut_mapping_name(options.color.gamut_mapping))),
      inputs_hash_(ContentHash().add(options_key_).hex()) {
  ShaderLibraryOptions library_options;
  library_options.lut_size = options.lut.size;
  library_options.coefficient_table_size = coefficient_table_size;
  library_options.embedded_luts = embedded_luts;
  library_options.ltc_size = runtime::shipped_ltc_table().size;
  library_options.analytic_lut = options.basis;
  if (per_material_) {
    library_options.further_layers.assign(runtime::kPerMaterialBases.begin() + 1,
                                          runtime::kPerMaterialBases.end());
  }
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(options.basis);
  glsl_library_ =
      shader_library_source(ShaderLanguage::glsl, shader_basis, library_options, inputs_hash_);
  hlsl_library_ =
      shader_library_source(ShaderLanguage::hlsl, shader_basis, library_options, inputs_hash_);
  wgsl_library_ =
      shader_library_source(ShaderLanguage::wgsl, shader_basis, library_options, inputs_hash_);
  library_options.coefficient_table_functions = false;
  library_options.area_light_functions = false;
  library_options.analytic_lut.reset();
  glsl_material_module_library_ =
      shader_library_source(ShaderLanguage::glsl, shader_basis, library_options, inputs_hash_);
}

const std::string& TextOutputs::library_source(ShaderLanguage language) const {
  switch (language) {
    case ShaderLanguage::hlsl:
      return hlsl_library_;
    case ShaderLanguage::wgsl:
      return wgsl_library_;
    case ShaderLanguage::glsl:
      break;
  }
  return glsl_library_;
}

std::string TextOutputs::material_inputs_hash(const Material& material) const {
  ContentHash hash;
  // The working space changes every material's numbers but none of the shared tables.
  hash.add(options_key_).add(color_key_).add(material.source_text);
  if (const auto* spectral = std::get_if<SpectralInput>(&material.model);
      spectral && !spectral->resolved_file.empty()) {
    hash.add(spectral->file_bytes);
  }
  return hash.hex();
}

std::string TextOutputs::material_source(ShaderLanguage language,
                                         const CompiledMaterial& compiled) const {
  return material_snippet_source(language, compiled, material_inputs_hash(compiled.material),
                                 per_material_);
}

std::string TextOutputs::material_json(const CompiledMaterial& compiled,
                                       std::string_view inputs_hash) const {
  nlohmann::ordered_json json =
      compiled_material_json(compiled, runtime::shipped_basis(compiled.basis), per_material_);
  json["inputs_hash"] = std::string(inputs_hash);
  return format_json(json);
}

}  // namespace matc
