#include "matc/api/text_outputs.h"

#include <stdexcept>

#include <fmt/format.h>

#include "checked_options.h"
#include "matc/emit/text_outputs.h"
#include "matc/fit/coefficient_table.h"
#include "matc/spirv/shader_language.h"

namespace matc::api {
namespace {

ShaderLanguage language_of(std::string_view name) {
  if (const auto language = shader_language_from_name(name)) return *language;
  throw std::invalid_argument(
      fmt::format("language: '{}' is not one of glsl, hlsl, wgsl", echoed(name)));
}

std::string color_key_of(const ColorOptions& color) {
  return fmt::format("{} {}", color_space_name(color.working_space),
                     gamut_mapping_name(color.gamut_mapping));
}

}  // namespace

TextOutputs::TextOutputs(const CompileOptions& options) {
  BuildOptions build;
  build.basis = basis_of(options);
  build.color = color_options_of(options);
  // `matc`'s default build: the default coefficient table, no embedded LUT.
  texts_ = std::make_shared<const matc::TextOutputs>(build, kDefaultCoefficientTableSize, nullptr);
  basis_ = std::string(runtime::basis_name(build.basis));
  color_key_ = color_key_of(build.color);
}

const std::string& TextOutputs::library_source(std::string_view language) const {
  return texts_->library_source(language_of(language));
}

namespace {

// A material's texts name its basis and colour options: the outputs must share them.
void check_same_options(const CompiledMaterial& compiled, const std::string& basis,
                        const std::string& color_key) {
  const std::string compiled_color = color_key_of(compiled.value().color);
  if (compiled.basis() != basis || compiled_color != color_key) {
    throw std::invalid_argument(fmt::format(
        "compiled: {} is compiled with basis {} and colour {}; these outputs are for basis {} "
        "and colour {}",
        echoed(compiled.name()), compiled.basis(), compiled_color, basis, color_key));
  }
}

}  // namespace

std::string TextOutputs::material_source(std::string_view language,
                                         const CompiledMaterial& compiled) const {
  check_same_options(compiled, basis_, color_key_);
  return texts_->material_source(language_of(language), compiled.value());
}

std::string TextOutputs::material_json(const CompiledMaterial& compiled) const {
  check_same_options(compiled, basis_, color_key_);
  return texts_->material_json(compiled.value(),
                               texts_->material_inputs_hash(compiled.value().material));
}

}  // namespace matc::api
