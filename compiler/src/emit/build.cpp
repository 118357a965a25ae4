#include "matc/emit/build.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "matc/emit/content_hash.h"
#include "matc/emit/material_module_template.h"
#include "matc/emit/material_snippet.h"
#include "matc/emit/shader_library.h"
#include "matc/json_format.h"
#include "matc/ltc/ltc_table_files.h"
#include "matc/lut/coefficient_table_files.h"
#include "matc/lut/default_lut_hashes.h"
#include "matc/material/parse.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/shader_basis.h"
#include "matc/spirv/linkage.h"
#include "matc/spirv/spirv_tools.h"
#include "matc/version.h"

namespace matc {
namespace {

// The shader snippets, in the order their files are written.
constexpr std::array<ShaderLanguage, 3> kShaderLanguages = {
    ShaderLanguage::glsl, ShaderLanguage::hlsl, ShaderLanguage::wgsl};

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

// A library module from GLSL: the source with a placeholder entry point, then exports.
SpirvWords library_module(std::string source, std::string name,
                          std::span<const std::string> exports) {
  source.insert(0, "#version 450\n");
  source.append("\nvoid main() {}\n");
  const SpirvWords compiled = compile_to_spirv(
      {ShaderLanguage::glsl, std::move(source), name, "main", /*keep_uncalled_functions=*/true});
  const SpirvWords library = export_functions(compiled, exports);
  validate_spirv(library, SpirvTarget::universal_1_3, name);
  return optimize_spirv(library, SpirvTarget::universal_1_3, name);
}

std::string spirv_bytes(const SpirvWords& words) {
  std::string bytes(words.size() * sizeof(std::uint32_t), '\0');
  for (std::size_t i = 0; i < words.size(); ++i) {
    for (std::size_t b = 0; b < 4; ++b)  // SPIR-V files are little-endian words
      bytes[4 * i + b] = static_cast<char>((words[i] >> (8 * b)) & 0xffu);
  }
  return bytes;
}

}  // namespace

std::vector<std::string> shared_library_exports(bool embedded_lut) {
  std::vector<std::string> names = {"matc_basis",
                                    "matc_fresnel",
                                    "matc_lut_texcoord",
                                    "matc_fresnel_preintegrated",
                                    "matc_energy_compensation",
                                    "matc_preintegrated_basis_analytic",
                                    "matc_coefficient_table_texcoord",
                                    "matc_channel_coefficients",
                                    "matc_coefficients_from_table",
                                    "matc_artistic_from_ior",
                                    "matc_coefficients_from_baked",
                                    "matc_ltc_texcoord",
                                    "matc_ltc_transform",
                                    "matc_ltc_quad_integral",
                                    "matc_ltc_disk_integral",
                                    "matc_ltc_sphere_integral",
                                    "matc_ltc_quad_light",
                                    "matc_ltc_disk_light",
                                    "matc_ltc_sphere_light"};
  if (embedded_lut) names.emplace_back("matc_preintegrated_basis_embedded");
  return names;
}

std::vector<std::string> material_library_exports(std::string_view material_name) {
  return {fmt::format("matc_fresnel_{}", material_name),
          fmt::format("matc_fresnel_preintegrated_{}", material_name)};
}

Build::Build(BuildOptions options) : options_(std::move(options)) {
  if (options_.embedded_lut_size != 0 && (options_.embedded_lut_size < kMinLutSize ||
                                          options_.embedded_lut_size > kMaxEmbeddedLutSize)) {
    throw std::invalid_argument(fmt::format("embedded LUT size {} outside [{}, {}]",
                                            options_.embedded_lut_size, kMinLutSize,
                                            kMaxEmbeddedLutSize));
  }
  const runtime::BasisView basis = this->basis();
  if (options_.embedded_lut_size != 0) {
    embedded_lut_ = preintegrate_lut(basis, {options_.embedded_lut_size, options_.lut.samples});
  }
  stored_coefficient_table_ =
      matc::stored_coefficient_table(options_.basis, options_.coefficient_table_precision);
  coefficient_table_file_ = shared_file_name(OutputKind::coefficient_table, options_.lut_format);
  coefficient_table_file_bytes_ = encode_coefficient_table(
      stored_coefficient_table_, options_.lut_format, options_.coefficient_table_precision);
  ltc_file_ = shared_file_name(OutputKind::ltc, options_.lut_format);
  ltc_file_bytes_ = encode_ltc_table(runtime::shipped_ltc_table(), options_.lut_format);
  inputs_hash_ = ContentHash().add(options_key()).hex();
  ShaderLibraryOptions library_options{options_.lut.size, stored_coefficient_table_.size(),
                                       embedded_lut()};
  library_options.ltc_size = runtime::shipped_ltc_table().size;
  library_options.analytic_lut = options_.basis;
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(options_.basis);
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

const Build::BakedTable& Build::baked_table() const {
  std::call_once(lazy_table_->once, [this] {
    BakedTable baked;
    baked.lut = bake_lut(basis(), options_.lut);
    baked.stored = stored_as(baked.lut.lut, options_.lut_precision);
    baked.file_bytes = encode_lut(baked.lut, options_.lut_format, options_.lut_precision);
    baked.hash = hash_of_bytes(baked.file_bytes);  // once: headers and the manifest name it
    lazy_table_->table = std::move(baked);
  });
  return *lazy_table_->table;
}

LutReference Build::lut_reference() const {
  // The default table's hash is checked in: naming it needs no bake.
  const auto known =
      default_lut_hash(options_.basis, options_.lut_format, options_.lut_precision, options_.lut);
  return {shared_file_name(OutputKind::lut, options_.lut_format), options_.lut.size,
          known ? std::string(*known) : baked_table().hash,
          std::string(runtime::basis_name(options_.basis))};
}

std::string Build::options_key() const {
  return fmt::format("lut {}x{} samples {} {} {} embed {} basis {}", options_.lut.size,
                     options_.lut.size, options_.lut.samples, lut_format_name(options_.lut_format),
                     lut_precision_name(options_.lut_precision), options_.embedded_lut_size,
                     runtime::basis_name(options_.basis));
}

runtime::BasisView Build::basis() const {
  return runtime::shipped_basis(options_.basis);
}

const std::string& Build::library_source(ShaderLanguage language) const {
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

std::string Build::material_source(ShaderLanguage language,
                                   const CompiledMaterial& compiled) const {
  return material_snippet_source(language, compiled, material_inputs_hash(compiled.material));
}

std::string Build::material_inputs_hash(const Material& material) const {
  ContentHash hash;
  // The working space changes every material's numbers but none of the shared tables.
  hash.add(options_key())
      .add(fmt::format("color {} gamut {}", color_space_name(options_.color.working_space),
                       gamut_mapping_name(options_.color.gamut_mapping)))
      .add(material.source_text);
  if (const auto* spectral = std::get_if<SpectralInput>(&material.model);
      spectral && !spectral->resolved_file.empty()) {
    hash.add(spectral->file_bytes);
  }
  return hash.hex();
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
    const std::string name = shared_file_name(OutputKind::spirv, options_.lut_format);
    files.push_back(
        {name, spirv_bytes(library_module(glsl_library_, name,
                                          shared_library_exports(embedded_lut_.has_value())))});
  }
  if (emit.contains(OutputKind::lut)) {
    const std::string file = lut_reference().file;
    files.push_back({file, baked_table().file_bytes});
    files.push_back({file + ".json", format_json(lut_manifest(this->lut(), options_.lut_format,
                                                              options_.lut_precision))});
  }
  if (emit.contains(OutputKind::coefficient_table)) {
    files.push_back({coefficient_table_file_, coefficient_table_file_bytes_});
    files.push_back(
        {coefficient_table_file_ + ".json",
         format_json(coefficient_table_manifest(stored_coefficient_table_, options_.lut_format,
                                                options_.coefficient_table_precision))});
  }
  if (emit.contains(OutputKind::ltc)) {
    files.push_back({ltc_file_, ltc_file_bytes_});
    files.push_back({ltc_file_ + ".json", format_json(ltc_table_manifest(
                                              runtime::shipped_ltc_table(), options_.lut_format))});
  }
  return files;
}

SpirvWords Build::material_library_module(const CompiledMaterial& compiled) const {
  return material_library_module(compiled, material_inputs_hash(compiled.material));
}

SpirvWords Build::material_library_module(const CompiledMaterial& compiled,
                                          std::string_view inputs_hash) const {
  // The template was compiled for the default table size (MATC_LUT_SIZE is in the module) and
  // no embedded table; it is empty in a bootstrap build.
  const std::span<const std::uint32_t> template_words =
      checked_in_material_module_template(options_.basis, compiled.fresnel_nonnegative);
  if (options_.lut.size == kDefaultLutSize && !embedded_lut_ && !template_words.empty())
    return patch_material_module(template_words, compiled);
  return compile_material_library_module(compiled, inputs_hash);
}

SpirvWords Build::compile_material_library_module(const CompiledMaterial& compiled) const {
  return compile_material_library_module(compiled, material_inputs_hash(compiled.material));
}

SpirvWords Build::compile_material_library_module(const CompiledMaterial& compiled,
                                                  std::string_view inputs_hash) const {
  const std::string& name = compiled.material.name;
  return library_module(glsl_material_module_library_ +
                            material_snippet_source(ShaderLanguage::glsl, compiled, inputs_hash),
                        material_file_name(OutputKind::spirv, name),
                        material_library_exports(name));
}

MaterialOutputs Build::material_outputs(const CompiledMaterial& compiled) const {
  const std::string& name = compiled.material.name;
  MaterialOutputs out{
      name, compiled.material.source_path, material_inputs_hash(compiled.material), {}};
  const auto& emit = options_.emit;
  for (const ShaderLanguage language : kShaderLanguages) {
    if (emit.contains(output_kind_of(language))) {
      out.files.push_back({material_file_name(output_kind_of(language), name),
                           material_snippet_source(language, compiled, out.inputs_hash)});
    }
  }
  if (emit.contains(OutputKind::spirv) || emit.contains(OutputKind::header)) {
    // The hash is computed once: it reads the material's input files.
    const SpirvWords module = material_library_module(compiled, out.inputs_hash);
    if (emit.contains(OutputKind::spirv))
      out.files.push_back({material_file_name(OutputKind::spirv, name), spirv_bytes(module)});
    if (emit.contains(OutputKind::header)) {
      out.files.push_back({material_file_name(OutputKind::header, name),
                           material_c_header(compiled, out.inputs_hash, lut_reference(), module)});
    }
  }
  if (emit.contains(OutputKind::json)) {
    nlohmann::ordered_json json = compiled_material_json(compiled, basis());
    json["inputs_hash"] = out.inputs_hash;
    out.files.push_back({material_file_name(OutputKind::json, name), format_json(json)});
  }
  return out;
}

nlohmann::ordered_json Build::description() const {
  nlohmann::ordered_json description;
  description["matc_version"] = kVersion;
  description["inputs_hash"] = inputs_hash_;
  std::vector<std::string> emitted;
  for (const OutputKind kind : options_.emit)
    emitted.emplace_back(layout_of(kind).name);
  description["emit"] = emitted;
  const LutReference lut_reference = this->lut_reference();
  description["basis"] = lut_reference.basis;
  description["color"] = {{"working_space", color_space_name(options_.color.working_space)},
                          {"gamut_mapping", gamut_mapping_name(options_.color.gamut_mapping)}};
  description["lut"] = {{"file", lut_reference.file},
                        {"size", options_.lut.size},
                        {"samples_per_texel", options_.lut.samples},
                        {"precision", lut_precision_name(options_.lut_precision)},
                        {"hash", lut_reference.hash},
                        {"embedded_size", options_.embedded_lut_size}};
  description["coefficient_table"] = {
      {"file", coefficient_table_file_},
      {"size", stored_coefficient_table_.size()},
      {"precision", lut_precision_name(options_.coefficient_table_precision)},
      {"hash", hash_of_bytes(coefficient_table_file_bytes_)}};
  description["ltc_table"] = {{"file", ltc_file_},
                              {"size", runtime::shipped_ltc_table().size},
                              {"precision", "f32"},
                              {"hash", hash_of_bytes(ltc_file_bytes_)}};
  return description;
}

}  // namespace matc
