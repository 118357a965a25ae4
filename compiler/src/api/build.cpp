#include "matc/api/build.h"

#include <stdexcept>

#include "base/json_format.h"
#include "checked_options.h"
#include "checked_values.h"
#include "emit/build.h"

namespace matc::api {
namespace {

static_assert(kMaxEmbeddedLutSize == matc::kMaxEmbeddedLutSize);

// The library's options from the public names, each checked.
matc::BuildOptions library_options(const BuildOptions& options) {
  matc::BuildOptions out;
  if (!options.emit.empty()) {
    out.emit.clear();
    for (const std::string& name : options.emit)
      out.emit.insert(checked_option_value<OutputKind>("emit", name));
  }
  out.lut.size = checked_count("lut_size", options.lut_size, kMinLutSize, kMaxLutSize);
  out.lut.samples = checked_count("lut_samples", options.lut_samples, 1, kMaxLutSamples);
  out.lut_format = option_from_name("lut_format", options.lut_format, out.lut_format);
  out.lut_precision = option_from_name("lut_precision", options.lut_precision, out.lut_precision);
  out.coefficient_table_precision =
      option_from_name("coefficient_table_precision", options.coefficient_table_precision,
                       out.coefficient_table_precision);
  if (options.embed_lut != 0)
    checked_count("embed_lut", options.embed_lut, kMinLutSize, kMaxEmbeddedLutSize);
  out.embedded_lut_size = options.embed_lut;
  const BasisChoice basis = basis_choice_of(options.compile);
  out.basis = basis.forced;
  out.per_material_basis = basis.per_material;
  out.color = color_options_of(options.compile);
  return out;
}

// The public options of a library build: every name filled in.
BuildOptions public_options(const matc::BuildOptions& options) {
  BuildOptions out;
  for (const OutputKind kind : options.emit)
    out.emit.emplace_back(output_kind_name(kind));
  out.lut_size = options.lut.size;
  out.lut_samples = options.lut.samples;
  out.lut_format = lut_format_name(options.lut_format);
  out.lut_precision = lut_precision_name(options.lut_precision);
  out.coefficient_table_precision = lut_precision_name(options.coefficient_table_precision);
  out.embed_lut = options.embedded_lut_size;
  out.compile = {std::string(option_name(BasisChoice{options.basis, options.per_material_basis})),
                 std::string(color_space_name(options.color.working_space)),
                 std::string(gamut_mapping_name(options.color.gamut_mapping))};
  return out;
}

std::vector<OutputFile> public_files(std::vector<matc::OutputFile> files) {
  std::vector<OutputFile> out;
  out.reserve(files.size());
  for (matc::OutputFile& file : files)
    out.push_back({std::move(file.name), std::move(file.bytes)});
  return out;
}

}  // namespace

Build::Build(const BuildOptions& options)
    : build_(std::make_shared<const matc::Build>(library_options(options))) {
  options_ = public_options(build_->options());
}

CompiledMaterial Build::compile(const Material& material) const {
  return api::compile(material, options_.compile);
}

const std::string& Build::library_source(std::string_view language) const {
  return build_->library_source(language_of(language));
}

std::string Build::material_source(std::string_view language,
                                   const CompiledMaterial& compiled) const {
  const ShaderLanguage chosen = language_of(language);
  check_same_options(compiled, build_->options());
  return build_->material_source(chosen, compiled.value());
}

std::vector<OutputFile> Build::material_files(const CompiledMaterial& compiled) const {
  check_same_options(compiled, build_->options());
  return public_files(build_->material_outputs(compiled.value()).files);
}

std::vector<OutputFile> Build::shared_files() const {
  return public_files(build_->shared_outputs());
}

PreintegratedTable Build::lut(std::string_view basis) const {
  const runtime::BasisKind layer = basis.empty()
                                       ? build_->lut_layers().front()
                                       : checked_option_value<runtime::BasisKind>("basis", basis);
  // Shares the build's table, which lives as long as the build: the table keeps the build alive.
  std::shared_ptr<const matc::Lut> lut(build_, &build_->stored_lut(layer));
  return {std::move(lut), std::string(runtime::basis_name(layer)), options_.lut_precision};
}

CoefficientTable Build::coefficient_table() const {
  std::shared_ptr<const matc::CoefficientTable> table(build_, &build_->stored_coefficient_table());
  return {std::move(table), options_.coefficient_table_precision};
}

std::string Build::description() const {
  return format_json(build_->description());
}

}  // namespace matc::api
