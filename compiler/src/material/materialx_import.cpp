// The importer: a MaterialX document's materials (materialx_document.h) through their shading
// model's record (materialx_models.h) into matc materials.
#include "material/materialx_import.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/echoed_text.h"
#include "material/basis_pin.h"
#include "materialx_document.h"
#include "materialx_models.h"
#include "suggestion.h"

namespace matc {
namespace {

using nlohmann::ordered_json;

class MaterialXImporter {
 public:
  MaterialXImporter(std::string_view text, const std::string& path)
      : document_(text, path, result_.diagnostics) {}

  MaterialXImport run() {
    if (!document_.readable()) return std::move(result_);
    const std::size_t found =
        document_.visit_materials([this](const MaterialXShader& shader) { import(shader); });
    if (result_.diagnostics.has_errors()) {
      result_.materials.clear();
    } else if (result_.materials.empty()) {
      result_.diagnostics.error(
          document_.whole_file(), "",
          found == 0 ? "the document holds no material (<surfacematerial> or <material>)"
                     : "none of its materials is a metal matc imports (see above)",
          fmt::format("a {} material with metalness above 0", materialx_shading_model_names()));
    }
    return std::move(result_);
  }

 private:
  struct InputValue {
    Rgb value{};
    bool given = false;  // false: the specification's default
    SourceLocation location;
  };

  // One input of the shader, or its default. Nullopt after an error, or after a warning when the
  // input is driven by a node (`connected` is then set).
  std::optional<InputValue> read(const MaterialXShader& shader, const MaterialXShadingModel& model,
                                 const MaterialXInputSpec& spec, bool& connected) {
    const std::string field = fmt::format("{}.{}", shader.name(), spec.name);
    const MaterialXInput input = document_.read_input(shader, spec.name, spec.type, field);
    switch (input.state) {
      case MaterialXInput::State::absent:
        return InputValue{spec.default_value, false, input.location};
      case MaterialXInput::State::value:
        return InputValue{input.value, true, input.location};
      case MaterialXInput::State::connected:
        connected = true;
        result_.diagnostics.warning(input.location, field, input.connection,
                                    connection_advice(input, model, spec));
        return std::nullopt;
      case MaterialXInput::State::invalid:
        break;
    }
    return std::nullopt;
  }

  static std::string connection_advice(const MaterialXInput& input,
                                       const MaterialXShadingModel& model,
                                       const MaterialXInputSpec& spec) {
    const std::string file = input.image_file.empty() ? "" : echoed(input.image_file, 128);
    if (spec.name == model.film_weight.name || spec.name == model.film_thickness.name ||
        spec.name == model.film_ior.name) {
      return "matc imports constant films only (a textured thickness is not compiled yet), so "
             "this material is skipped";
    }
    if (spec.name == model.coat_roughness.name) {
      return "the coat's roughness is left out of the imported material (its default is used)";
    }
    if (spec.name == model.coat_weight.name || spec.name == model.coat_color.name ||
        spec.name == model.coat_ior.name) {
      std::string advice = "matc imports constant coats only, so this material is skipped";
      if (!file.empty()) {
        advice += fmt::format(
            "; it is a plain image read of '{}', and `matc bake` does not bake coat maps yet",
            file);
      }
      return advice;
    }
    const bool fresnel_input = spec.name != model.roughness.name;
    std::string advice = fresnel_input
                             ? "matc imports constant metals only, so this material is skipped"
                             : "the roughness is left out of the imported material";
    if (!file.empty() && fresnel_input && model.bakes_image_maps) {
      advice += fmt::format(
          "; it is a plain image read of '{}': `matc bake --reflectivity {} --edge-tint G` bakes "
          "it as a textured metal (docs/baking.md), with G = {} x {} and the map scaled by {} if "
          "{} is not 1",
          file, file, model.edge_weight.name, model.edge_color.name, model.weight.name,
          model.weight.name);
    } else if (!file.empty() && fresnel_input) {
      advice += fmt::format(
          "; it is a plain image read of '{}', and `matc bake` does not bake {} maps yet", file,
          model.imported == ImportedModel::f82_tint ? "F82-tint" : "these");
    }
    return advice;
  }

  void import(const MaterialXShader& shader) {
    const std::string element_name = shader.name();
    const MaterialXShadingModel* model = find_materialx_shading_model(shader.model);
    if (!model) {
      result_.diagnostics.note(
          document_.at(*shader.material), element_name,
          shader.model.empty()
              ? "names no shading model; skipped"
              : fmt::format("uses the shading model '{}', which matc does not import; skipped",
                            echoed(shader.model)),
          materialx_shading_model_names());
      return;
    }
    if (!check_inputs(shader, *model)) return;
    // A connected Fresnel input is warned about and leaves its value unset: the material is
    // skipped, since matc imports constant metals only.
    bool connected = false;
    const auto weight = read(shader, *model, model->weight, connected);
    const auto color = read(shader, *model, model->color, connected);
    const auto metalness = read(shader, *model, model->metalness, connected);
    const auto edge_weight = read(shader, *model, model->edge_weight, connected);
    const auto edge_color = read(shader, *model, model->edge_color, connected);
    bool roughness_connected = false;
    const auto roughness = read(shader, *model, model->roughness, roughness_connected);
    if (!weight || !color || !metalness || !edge_weight || !edge_color) return;
    if (!roughness && !roughness_connected) return;
    bool coat_connected = false;
    const auto coat_weight = read(shader, *model, model->coat_weight, coat_connected);
    if (!coat_weight) return;

    const double metal = metalness->value[0];
    const std::string metal_field = fmt::format("{}.{}", element_name, model->metalness.name);
    if (metal < 0.0 || metal > 1.0) {
      result_.diagnostics.error(metalness->location, metal_field,
                                fmt::format("{} is out of range", metal), "a number in [0, 1]");
      return;
    }
    if (metal == 0.0) {
      result_.diagnostics.note(
          document_.at(*shader.material), element_name,
          fmt::format("is not metallic ({} {}); skipped", model->metalness.name,
                      metalness->given ? "0" : "absent, so 0"));
      return;
    }
    if (metal < 1.0) {
      result_.diagnostics.note(
          metalness->location, metal_field,
          fmt::format("{} is a partial metal: matc compiles its metal lobe's Fresnel, and the "
                      "engine blends it with its dielectric lobe by {} as {} does",
                      metal, metal, model->node));
    }
    if (roughness && (roughness->value[0] < 0.0 || roughness->value[0] > 1.0)) {
      result_.diagnostics.error(
          roughness->location, fmt::format("{}.{}", element_name, model->roughness.name),
          fmt::format("{} is out of range", roughness->value[0]), "a number in [0, 1]");
      return;
    }
    note_not_carried(shader, *model, element_name);

    Rgb f0{};
    Rgb edge{};
    for (std::size_t c = 0; c < 3; ++c) {
      f0[c] = weight->value[0] * color->value[c];
      edge[c] = model->edge_scaled_by_weight ? edge_weight->value[0] * edge_color->value[c]
                                             : edge_color->value[c];
    }
    clamp_channels(f0, 0.0, model->max_f0, color->location, element_name, model->f0_words,
                   model->f0_range);
    clamp_channels(edge, 0.0, 1.0, edge_color->location, element_name, model->edge_words,
                   "[0, 1], the range matc's model takes");
    if (!model->edge_scaled_by_weight && edge_weight->given && edge_weight->value[0] != 1.0) {
      result_.diagnostics.note(
          edge_weight->location, fmt::format("{}.{}", element_name, model->edge_weight.name),
          fmt::format("{} scales OpenPBR's metal Fresnel (min(1, weight x F)); matc compiles F "
                      "itself, so apply the weight in the engine",
                      edge_weight->value[0]));
    }

    ordered_json material_json;
    material_json["name"] = material_name(element_name, *shader.material);
    material_json["description"] =
        fmt::format("Imported from {} (material '{}', {}{})",
                    std::filesystem::path(document_.path()).filename().string(), element_name,
                    model->node, metal < 1.0 ? fmt::format(", metal lobe of {}", metal) : "");
    material_json["color_space"] = color_space_name(document_.color_space());
    const auto rgb = [](const Rgb& v) { return ordered_json::array({v[0], v[1], v[2]}); };
    if (model->imported == ImportedModel::artistic) {
      material_json["artistic"] = {{"reflectivity", rgb(f0)}, {"edge_tint", rgb(edge)}};
    } else {
      material_json["f82_tint"] = {{"f0", rgb(f0)}, {"tint", rgb(edge)}};
    }
    if (roughness) material_json["roughness"] = roughness->value[0];
    if (coat_weight->value[0] != 0.0) {
      auto coat =
          read_coat(shader, *model, element_name, coat_weight->value[0], coat_weight->location);
      if (!coat) return;
      material_json["coat"] = std::move(*coat);
    }
    const ImportedFilm film = read_film(shader, *model, element_name);
    if (!film.ok) return;
    // OpenPBR's film lies on the base, under the coat: matc sees it from the coat's medium.
    if (film.block) material_json["film"] = *film.block;
    if (shader.material->has_attribute(kBasisPinAttribute)) {
      const std::string_view layered = material_json.contains("coat")   ? "coat"
                                       : material_json.contains("film") ? "film"
                                                                        : "";
      const BasisPin pin = read_basis_pin(shader.material->attribute(kBasisPinAttribute), layered);
      if (pin.problem) {
        result_.diagnostics.error(document_.at(*shader.material),
                                  fmt::format("{}.{}", element_name, kBasisPinAttribute),
                                  pin.problem->problem, pin.problem->allowed);
        return;
      }
      material_json["basis"] = runtime::basis_name(*pin.basis);
    }
    if (material_json["name"].get<std::string>().empty()) return;  // a name clash, reported
    add_imported_material(result_, material_json, document_.path(), document_.at(*shader.material),
                          material_json["name"].get<std::string>());
  }

  // The coat block of a material whose coat weight is above 0: its weight, colour, roughness and
  // index, checked or clamped to what matc compiles. Nullopt after an error, or a warning for a
  // connected input that skips the material.
  std::optional<ordered_json> read_coat(const MaterialXShader& shader,
                                        const MaterialXShadingModel& model,
                                        const std::string& element_name, double weight,
                                        const SourceLocation& weight_location) {
    bool connected = false;
    const auto color = read(shader, model, model.coat_color, connected);
    bool roughness_connected = false;
    const auto roughness = read(shader, model, model.coat_roughness, roughness_connected);
    const auto ior = read(shader, model, model.coat_ior, connected);
    if (!color || !ior || (!roughness && !roughness_connected)) return std::nullopt;
    const auto field = [&](const MaterialXInputSpec& spec) {
      return fmt::format("{}.{}", element_name, spec.name);
    };
    if (weight < 0.0 || weight > 1.0) {
      result_.diagnostics.error(weight_location, field(model.coat_weight),
                                fmt::format("{} is out of range", weight), "a number in [0, 1]");
      return std::nullopt;
    }
    const double coat_roughness =
        roughness ? roughness->value[0] : model.coat_roughness.default_value[0];
    if (coat_roughness < 0.0 || coat_roughness > 1.0) {
      result_.diagnostics.error(roughness->location, field(model.coat_roughness),
                                fmt::format("{} is out of range", coat_roughness),
                                "a number in [0, 1]");
      return std::nullopt;
    }
    Rgb tint = color->value;
    clamp_channels(tint, 0.0, 1.0, color->location, element_name, "coat colour",
                   "[0, 1], a transmittance");
    double index = ior->value[0];
    if (index < kMinCoatIor || index > 3.0) {
      const double clamped = std::clamp(index, kMinCoatIor, 3.0);
      result_.diagnostics.warning(
          ior->location, field(model.coat_ior), fmt::format("{} is clamped to {}", index, clamped),
          fmt::format("[{}, 3], the coat indices matc compiles (docs/coating.md)", kMinCoatIor));
      index = clamped;
    }
    const auto rgb = [](const Rgb& v) { return ordered_json::array({v[0], v[1], v[2]}); };
    return ordered_json{
        {"weight", weight}, {"ior", index}, {"roughness", coat_roughness}, {"color", rgb(tint)}};
  }

  // The film block of a material whose film weight (or, without one, thickness) is above 0;
  // ok is false after an error or a connected input, which skips the material.
  struct ImportedFilm {
    bool ok = true;
    std::optional<ordered_json> block;
    SourceLocation location;
  };

  ImportedFilm read_film(const MaterialXShader& shader, const MaterialXShadingModel& model,
                         const std::string& element_name) {
    bool connected = false;
    const auto thickness = read(shader, model, model.film_thickness, connected);
    const auto ior = read(shader, model, model.film_ior, connected);
    std::optional<InputValue> weight;
    if (!model.film_weight.name.empty()) weight = read(shader, model, model.film_weight, connected);
    if (!thickness || !ior || (!model.film_weight.name.empty() && !weight))
      return {false, std::nullopt, {}};
    const auto field = [&](const MaterialXInputSpec& spec) {
      return fmt::format("{}.{}", element_name, spec.name);
    };
    const double coverage = weight ? weight->value[0] : (thickness->value[0] > 0.0 ? 1.0 : 0.0);
    if (coverage < 0.0 || coverage > 1.0) {
      result_.diagnostics.error(weight->location, field(model.film_weight),
                                fmt::format("{} is out of range", coverage), "a number in [0, 1]");
      return {false, std::nullopt, {}};
    }
    if (coverage == 0.0) return {true, std::nullopt, {}};
    const double nm = thickness->value[0] * model.film_thickness_to_nm;
    if (!(nm >= 0.0 && nm <= kMaxFilmThicknessNm)) {
      result_.diagnostics.error(
          thickness->location, field(model.film_thickness),
          fmt::format("{} is out of range", thickness->value[0]),
          fmt::format(
              "a number in [0, {}] ({} in {})", kMaxFilmThicknessNm / model.film_thickness_to_nm,
              model.film_thickness_to_nm == 1.0 ? "nanometres" : "micrometres", model.node));
      return {false, std::nullopt, {}};
    }
    double index = ior->value[0];
    if (index < kMinFilmIor || index > kMaxFilmIor) {
      const double clamped = std::clamp(index, kMinFilmIor, kMaxFilmIor);
      result_.diagnostics.warning(
          ior->location, field(model.film_ior), fmt::format("{} is clamped to {}", index, clamped),
          fmt::format("[{}, {}], the film indices matc compiles", kMinFilmIor, kMaxFilmIor));
      index = clamped;
    }
    return {true, ordered_json{{"weight", coverage}, {"ior", index}, {"thickness", nm}},
            thickness->location};
  }

  void clamp_channels(Rgb& values, double low, double high, const SourceLocation& location,
                      const std::string& material, std::string_view what, std::string_view range) {
    Rgb clamped = values;
    for (double& value : clamped)
      value = std::clamp(value, low, high);
    if (clamped == values) return;
    result_.diagnostics.warning(
        location, material,
        fmt::format("{} is ({:.4g}, {:.4g}, {:.4g}), clamped to ({:.4g}, {:.4g}, {:.4g})", what,
                    values[0], values[1], values[2], clamped[0], clamped[1], clamped[2]),
        std::string(range));
    values = clamped;
  }

  // Each input at most once (of two, one would silently win), and only the inputs the node
  // definition declares (a misspelt input, or one of the other shading model, would silently do
  // nothing): a duplicate is an error, an unknown input a warning with the nearest known name.
  bool check_inputs(const MaterialXShader& shader, const MaterialXShadingModel& model) {
    std::map<std::string, SourceLocation> seen;
    bool unique = true;
    for (const XmlElement* input : shader.node->children) {
      if (input->name != shader.input_tag) continue;
      const std::string name(input->attribute("name"));
      const SourceLocation location = document_.at(*input);
      const std::string field = fmt::format("{}.{}", shader.name(), echoed(name));
      const auto [first, inserted] = seen.emplace(name, location);
      if (!inserted) {
        result_.diagnostics.error(location, field,
                                  fmt::format("is given twice (first at {}:{})", first->second.line,
                                              first->second.column),
                                  "each input of a shader node at most once");
        unique = false;
        continue;
      }
      if (std::find(model.inputs.begin(), model.inputs.end(), name) != model.inputs.end()) continue;
      std::string message = fmt::format("is not an input of {}; ignored", model.node);
      for (const MaterialXShadingModel& other : materialx_shading_models()) {
        if (other.node != model.node &&
            std::find(other.inputs.begin(), other.inputs.end(), name) != other.inputs.end())
          message = fmt::format("is an input of {}, not of {}; ignored", other.node, model.node);
      }
      if (const auto suggestion = closest_match(name, model.inputs))
        message += fmt::format(" (did you mean '{}'?)", *suggestion);
      result_.diagnostics.warning(
          location, field, message,
          fmt::format("the inputs MaterialX's node definition of {} declares", model.node));
    }
    return unique;
  }

  void note_not_carried(const MaterialXShader& shader, const MaterialXShadingModel& model,
                        const std::string& material) {
    std::string list;
    for (const NotCarriedInput& entry : model.not_carried) {
      if (document_.is_neutral(shader, entry.name, entry.neutral)) continue;
      list += fmt::format("{}{}", list.empty() ? "" : ", ", entry.name);
    }
    if (list.empty()) return;
    result_.diagnostics.note(document_.at(*shader.material), material,
                             fmt::format("not carried: {} (matc compiles the metal's Fresnel; "
                                         "docs/interchange.md lists what is left out and why)",
                                         list));
  }

  // The matc name for a material element: sanitised, and unique in the document ignoring case.
  // Empty after reporting a clash.
  std::string material_name(const std::string& element_name, const XmlElement& material) {
    const SourceLocation location = document_.at(material);
    return names_.claim(
        element_name, location, element_name,
        fmt::format("material '{}' at {}:{}", element_name, location.line, location.column),
        result_.diagnostics);
  }

  MaterialXImport result_;  // before document_, which reports into its diagnostics
  MaterialXDocument document_;
  DocumentNames names_;
};

}  // namespace

MaterialXImport import_materialx(std::string_view text, const std::string& path) {
  return MaterialXImporter(text, path).run();
}

}  // namespace matc
