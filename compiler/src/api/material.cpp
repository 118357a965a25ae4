#include "matc/api/material.h"

#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "input_files.h"
#include "material/material_input.h"
#include "material/materialx_import.h"
#include "material/memory_files.h"
#include "material/parse.h"
#include "optics/color_space.h"
#include "optics/presets.h"
#include "public_diagnostics.h"

namespace matc::api {
namespace {

std::vector<Material> materials_of(MaterialInput input) {
  throw_if_errors(input.diagnostics);
  const std::vector<Diagnostic> diagnostics = public_diagnostics(input.diagnostics);
  std::vector<Material> materials;
  materials.reserve(input.materials.size());
  for (matc::Material& material : input.materials)
    materials.emplace_back(std::make_shared<const matc::Material>(std::move(material)),
                           diagnostics);
  return materials;
}

}  // namespace

Material::Material(std::shared_ptr<const matc::Material> value, std::vector<Diagnostic> diagnostics)
    : value_(std::move(value)), diagnostics_(std::move(diagnostics)) {}

const std::string& Material::name() const {
  return value_->name;
}
std::string Material::model() const {
  return std::string(model_key(value_->model));
}
const std::string& Material::path() const {
  return value_->source_path;
}
const std::string& Material::json() const {
  return value_->source_text;
}
bool Material::coated() const {
  return value_->coat.has_value();
}

ModelInputs Material::inputs() const {
  ModelInputs inputs;
  std::visit(
      [&](const auto& input) {
        using Input = std::decay_t<decltype(input)>;
        if constexpr (std::is_same_v<Input, ArtisticInput>) {
          inputs.colors = {{"reflectivity", input.reflectivity}, {"edge_tint", input.edge_tint}};
        } else if constexpr (std::is_same_v<Input, IorInput>) {
          inputs.colors = {{"n", input.n}, {"k", input.k}};
        } else if constexpr (std::is_same_v<Input, SpectralInput>) {
          if (!input.preset.empty()) inputs.texts.emplace_back("preset", input.preset);
          if (!input.file.empty()) inputs.texts.emplace_back("file", input.file);
        } else {
          inputs.colors = {{"f0", input.f0}, {"tint", input.tint}};
        }
      },
      value_->model);
  return inputs;
}

std::optional<double> Material::roughness() const {
  return value_->roughness;
}

std::optional<std::string> Material::color_space() const {
  if (!value_->color_space) return std::nullopt;
  return std::string(color_space_name(*value_->color_space));
}

std::vector<Material> parse_materials(std::string_view text, std::string_view path) {
  return materials_of(parse_material_input(text, std::string(path)));
}

std::vector<Material> parse_materials(std::string_view text, std::string_view path,
                                      const InputFiles& files) {
  check_input_files(files);
  const std::string input(path);
  return materials_of(parse_material_input(text, input, memory_file_loader(files, input)));
}

Material parse_material_json(std::string_view json, std::string_view path) {
  ParseResult parsed = parse_material(json, std::string(path));
  throw_if_errors(parsed.diagnostics);
  return Material(std::make_shared<const matc::Material>(std::move(*parsed.material)),
                  public_diagnostics(parsed.diagnostics));
}

std::vector<Material> load_materials(std::string_view path) {
  return materials_of(read_material_input(std::string(path)));
}

bool reads_materialx() {
  return true;
}

std::vector<std::string> spectral_presets() {
  std::vector<std::string> names;
  for (const MetalPreset& preset : metal_presets())
    names.emplace_back(preset.symbol);
  return names;
}

}  // namespace matc::api
