#include "matc/api/text_outputs.h"

#include "checked_options.h"
#include "emit/text_outputs.h"
#include "fit/coefficient_table.h"

namespace matc::api {

TextOutputs::TextOutputs(const CompileOptions& options) {
  matc::BuildOptions build;
  const BasisChoice basis = basis_choice_of(options);
  build.basis = basis.forced;
  build.per_material_basis = basis.per_material;
  build.color = color_options_of(options);
  // `matc`'s default build: the default coefficient table, no embedded LUT.
  texts_ = std::make_shared<const matc::TextOutputs>(build, kDefaultCoefficientTableSize,
                                                     std::span<const Lut>{});
  basis_ = std::string(option_name(basis));
  color_key_ = color_key_of(build.color);
}

const std::string& TextOutputs::library_source(std::string_view language) const {
  return texts_->library_source(language_of(language));
}

std::string TextOutputs::material_source(std::string_view language,
                                         const CompiledMaterial& compiled) const {
  check_same_options(compiled, expected_basis(compiled, basis_), color_key_);
  return texts_->material_source(language_of(language), compiled.value());
}

std::string TextOutputs::material_json(const CompiledMaterial& compiled) const {
  check_same_options(compiled, expected_basis(compiled, basis_), color_key_);
  return texts_->material_json(compiled.value(),
                               texts_->material_inputs_hash(compiled.value().material));
}

}  // namespace matc::api
