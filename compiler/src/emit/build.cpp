#include "emit/build.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "base/content_hash.h"
#include "base/json_format.h"
#include "emit/layer_suffix.h"
#include "emit/library_module.h"
#include "emit/library_module_cache.h"
#include "emit/material_module_template.h"
#include "emit/material_snippet.h"
#include "lut/film_table_files.h"
#include "matc/runtime/shader_basis.h"
#include "matc/version.h"
#include "material/parse.h"

namespace matc {
namespace {

OutputKind output_kind_of(ShaderLanguage language) {
  switch (language) {
    case ShaderLanguage::hlsl:
      return OutputKind::hlsl;
    case ShaderLanguage::wgsl:
      return OutputKind::wgsl;
    case ShaderLanguage::glsl:
      break;
  }
  return OutputKind::glsl;
}

// The options, checked: a Build is only made from options in range.
BuildOptions checked(BuildOptions options) {
  if (options.embedded_lut_size != 0 && (options.embedded_lut_size < kMinLutSize ||
                                         options.embedded_lut_size > kMaxEmbeddedLutSize)) {
    throw std::invalid_argument(fmt::format("embedded LUT size {} outside [{}, {}]",
                                            options.embedded_lut_size, kMinLutSize,
                                            kMaxEmbeddedLutSize));
  }
  if (options.per_material_basis) {
    if (options.basis != runtime::kPerMaterialBases.front()) {
      throw std::invalid_argument(
          fmt::format("a per-material build's first basis is {}, not {}",
                      runtime::basis_name(runtime::kPerMaterialBases.front()),
                      runtime::basis_name(options.basis)));
    }
  }
  return options;
}

std::vector<runtime::BasisKind> table_layers(const BuildOptions& options) {
  if (options.per_material_basis)
    return {runtime::kPerMaterialBases.begin(), runtime::kPerMaterialBases.end()};
  return {options.basis};
}

SharedTableOptions table_options(const BuildOptions& options) {
  return {table_layers(options),
          options.lut,
          options.lut_format,
          options.lut_precision,
          options.coefficient_table_precision,
          options.embedded_lut_size};
}

}  // namespace

Build::Build(BuildOptions options)
    : options_(checked(std::move(options))),
      tables_(table_options(options_)),
      texts_(options_, tables_.stored_coefficient_table().size(), tables_.embedded_luts()) {}

runtime::BasisView Build::basis() const {
  return runtime::shipped_basis(options_.basis);
}

BasisChoice Build::basis_choice() const {
  return {options_.basis, options_.per_material_basis};
}

runtime::BasisView Build::basis_for(const Material& material) const {
  return runtime::shipped_basis(chosen_basis(material, basis_choice()));
}

std::vector<OutputFile> Build::shared_outputs() const {
  std::vector<OutputFile> files;
  const auto& emit = options_.emit;
  for (const ShaderLanguage language : kShaderLanguages) {
    if (emit.contains(output_kind_of(language))) {
      files.push_back({shared_file_name(output_kind_of(language), options_.lut_format),
                       library_source(language)});
    }
  }
  if (emit.contains(OutputKind::spirv)) {
    LibraryModuleInputs inputs = shared_library_module_inputs();
    files.push_back(
        {inputs.name, spirv_file_bytes(cached_or_compiled_library_module(
                          std::move(inputs.glsl_source), inputs.name, inputs.exports))});
  }
  for (OutputFile& table : tables_.files(emit))
    files.push_back(std::move(table));
  return files;
}

Build::LibraryModuleInputs Build::shared_library_module_inputs() const {
  std::vector<std::string> further_layer_suffixes;
  for (std::size_t layer = 1; layer < lut_layers().size(); ++layer)
    further_layer_suffixes.push_back(layer_suffix(lut_layers()[layer]));
  return {library_source(ShaderLanguage::glsl),
          shared_file_name(OutputKind::spirv, options_.lut_format),
          shared_library_exports(!tables_.embedded_luts().empty(), further_layer_suffixes)};
}

SpirvWords Build::material_library_module(const CompiledMaterial& compiled) const {
  return material_library_module(compiled, material_inputs_hash(compiled.material));
}

SpirvWords Build::material_library_module(const CompiledMaterial& compiled,
                                          std::string_view inputs_hash) const {
  // The template was compiled for the default table size (MATC_LUT_SIZE is in the module) and
  // no embedded table; it is empty in a bootstrap build.
  // A filmed metal's functions read its table: no coefficient and no clamp in its module.
  const bool filmed = compiled.film_table.has_value();
  const std::span<const std::uint32_t> template_words = checked_in_material_module_template(
      compiled.basis, compiled.fresnel_nonnegative && !filmed, options_.per_material_basis, filmed);
  // The checked-in templates are bare and filmed materials' modules; a coated one is compiled.
  if (options_.lut.size == kDefaultLutSize && tables_.embedded_luts().empty() &&
      !template_words.empty() && !compiled.coat)
    return patch_material_module(template_words, compiled);
  return compile_material_library_module(compiled, inputs_hash);
}

SpirvWords Build::compile_material_library_module(const CompiledMaterial& compiled) const {
  return compile_material_library_module(compiled, material_inputs_hash(compiled.material));
}

SpirvWords Build::compile_material_library_module(const CompiledMaterial& compiled,
                                                  std::string_view inputs_hash) const {
  const std::string& name = compiled.material.name;
  return compile_library_module(
      texts_.material_module_library() + material_snippet_source(ShaderLanguage::glsl, compiled,
                                                                 inputs_hash,
                                                                 options_.per_material_basis),
      material_file_name(OutputKind::spirv, name),
      material_library_exports(name, compiled.coat.has_value()));
}

MaterialOutputs Build::material_outputs(const CompiledMaterial& compiled) const {
  const std::string& name = compiled.material.name;
  MaterialOutputs out{
      name, compiled.material.source_path, material_inputs_hash(compiled.material), {}};
  const auto& emit = options_.emit;
  for (const ShaderLanguage language : kShaderLanguages) {
    if (emit.contains(output_kind_of(language))) {
      out.files.push_back({material_file_name(output_kind_of(language), name),
                           material_snippet_source(language, compiled, out.inputs_hash,
                                                   options_.per_material_basis)});
    }
  }
  if (emit.contains(OutputKind::spirv) || emit.contains(OutputKind::header)) {
    // The hash is computed once: it reads the material's input files.
    const SpirvWords module = material_library_module(compiled, out.inputs_hash);
    if (emit.contains(OutputKind::spirv))
      out.files.push_back({material_file_name(OutputKind::spirv, name), spirv_file_bytes(module)});
    if (emit.contains(OutputKind::header)) {
      out.files.push_back(
          {material_file_name(OutputKind::header, name),
           material_c_header(compiled, out.inputs_hash, tables_.lut_reference(), module,
                             options_.per_material_basis
                                 ? std::optional<std::size_t>(lut_layer(compiled.basis))
                                 : std::nullopt)});
    }
  }
  if (emit.contains(OutputKind::json)) {
    out.files.push_back({material_file_name(OutputKind::json, name),
                         texts_.material_json(compiled, out.inputs_hash)});
  }
  // A filmed metal's own table goes with the tables, in their format and precision.
  if (compiled.film_table && emit.contains(OutputKind::lut)) {
    // A thickness per pixel: the stack, whose last slice is film_table.
    out.files.push_back({film_table_file_name(name, options_.lut_format),
                         compiled.film_stack
                             ? encode_film_table(*compiled.film_stack, options_.lut_format,
                                                 options_.lut_precision, name)
                             : encode_film_table(*compiled.film_table, options_.lut_format,
                                                 options_.lut_precision, name)});
  }
  return out;
}

nlohmann::ordered_json Build::description() const {
  nlohmann::ordered_json description;
  description["matc_version"] = kVersion;
  description["inputs_hash"] = inputs_hash();
  std::vector<std::string> emitted;
  for (const OutputKind kind : options_.emit)
    emitted.emplace_back(layout_of(kind).name);
  description["emit"] = emitted;
  if (options_.per_material_basis) {
    description["basis"] = "auto";
    std::vector<std::string> layers;
    for (const runtime::BasisKind basis : tables_.layers())
      layers.emplace_back(runtime::basis_name(basis));
    description["lut_layers"] = layers;
  } else {
    description["basis"] = std::string(runtime::basis_name(options_.basis));
  }
  description["color"] = {{"working_space", color_space_name(options_.color.working_space)},
                          {"gamut_mapping", gamut_mapping_name(options_.color.gamut_mapping)}};
  tables_.describe(description);
  return description;
}

}  // namespace matc
