#include "matc/material/materialx_import.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "matc/optics/color_space.h"

namespace matc {
namespace {

using nlohmann::ordered_json;

enum class ValueType { float1, color3 };

struct InputSpec {
  std::string_view name;
  ValueType type;
  Rgb default_value;  // a float's default in [0]
};

// An input that changes a metal's look but is not carried, and the value at which it changes
// nothing (weights 0, opacities 1, booleans false): only other values are reported.
struct NotCarried {
  std::string_view name;
  double neutral = 0.0;
};

// One shading model: the inputs its metal depends on (with their specification defaults), and
// the inputs that change a metal's look but are not carried.
struct ShadingModel {
  std::string_view node;  // "standard_surface" or "open_pbr_surface"
  InputSpec weight;       // scales F0: base / base_weight
  InputSpec color;        // F0 colour: base_color
  InputSpec metalness;    // metalness / base_metalness
  InputSpec edge_weight;  // specular / specular_weight
  InputSpec edge_color;   // specular_color
  InputSpec roughness;    // specular_roughness
  std::array<NotCarried, 10> not_carried;
};

// Defaults: Autodesk Standard Surface 1.0.1 as MaterialX's nodedef declares it, and OpenPBR
// Surface 1.1's parameter reference.
constexpr ShadingModel kStandardSurface = {
    "standard_surface",
    {"base", ValueType::float1, {0.8, 0.0, 0.0}},
    {"base_color", ValueType::color3, {1.0, 1.0, 1.0}},
    {"metalness", ValueType::float1, {0.0, 0.0, 0.0}},
    {"specular", ValueType::float1, {1.0, 0.0, 0.0}},
    {"specular_color", ValueType::color3, {1.0, 1.0, 1.0}},
    {"specular_roughness", ValueType::float1, {0.2, 0.0, 0.0}},
    {{{"coat"},
      {"sheen"},
      {"thin_film_thickness"},
      {"specular_anisotropy"},
      {"transmission"},
      {"subsurface"},
      {"emission"},
      {"diffuse_roughness"},
      {"coat_affect_color"},
      {"opacity", 1.0}}},
};
constexpr ShadingModel kOpenPbrSurface = {
    "open_pbr_surface",
    {"base_weight", ValueType::float1, {1.0, 0.0, 0.0}},
    {"base_color", ValueType::color3, {0.8, 0.8, 0.8}},
    {"base_metalness", ValueType::float1, {0.0, 0.0, 0.0}},
    {"specular_weight", ValueType::float1, {1.0, 0.0, 0.0}},
    {"specular_color", ValueType::color3, {1.0, 1.0, 1.0}},
    {"specular_roughness", ValueType::float1, {0.3, 0.0, 0.0}},
    {{{"coat_weight"},
      {"fuzz_weight"},
      {"thin_film_weight"},
      {"specular_roughness_anisotropy"},
      {"transmission_weight"},
      {"subsurface_weight"},
      {"emission_luminance"},
      {"base_diffuse_roughness"},
      {"geometry_opacity", 1.0},
      {"geometry_thin_walled"}}},
};

const ShadingModel* find_shading_model(std::string_view node) {
  for (const ShadingModel* model : {&kStandardSurface, &kOpenPbrSurface})
    if (model->node == node) return model;
  return nullptr;
}

// MaterialX's artistic_ior clamps the reflectivity to [0, 0.99] (Gulbrandsen's n_max is infinite
// at 1); chrome-like looks that ask for 1 get 0.99 there, so they get it here too.
constexpr double kMaxArtisticReflectivity = 0.99;

std::string_view type_name(ValueType type) {
  return type == ValueType::float1 ? "float" : "color3";
}

bool is_connected(const pugi::xml_node& input) {
  for (const char* attribute : {"nodename", "nodegraph", "output", "interfacename"})
    if (!input.attribute(attribute).empty()) return true;
  return false;
}

// The material element and the shader it uses, in either document form.
struct SurfaceMaterial {
  pugi::xml_node material;  // <surfacematerial> or <material>
  pugi::xml_node shader;    // <standard_surface ...> node, or the <shaderref>
  std::string model;        // the shading model's node name
  const char* input_tag;    // "input" or "bindinput"
};

class Importer {
 public:
  Importer(std::string_view text, const std::string& path) : text_(text), locator_(path, text) {}

  MaterialXImport run() {
    const pugi::xml_parse_result parsed =
        document_.load_buffer(text_.data(), text_.size(),
                              pugi::parse_default | pugi::parse_trim_pcdata, pugi::encoding_utf8);
    if (!parsed) {
      result_.diagnostics.error(
          locator_.at(static_cast<std::size_t>(std::max<std::ptrdiff_t>(parsed.offset, 0))), "",
          fmt::format("malformed XML: {}", parsed.description()), "a MaterialX document (XML)");
      return std::move(result_);
    }
    root_ = document_.document_element();
    if (std::string_view(root_.name()) != "materialx") {
      result_.diagnostics.error(at(root_), "",
                                fmt::format("the root element is <{}>", root_.name()),
                                "a MaterialX document, whose root element is <materialx>");
      return std::move(result_);
    }
    check_version();
    if (!read_document_space()) return std::move(result_);
    std::size_t elements = 0;
    for (const pugi::xml_node& node : root_.children()) {
      if (node.type() != pugi::node_element) continue;
      if (++elements > kMaxMaterialXElements) {
        result_.diagnostics.error(
            at(node), "",
            fmt::format("the document has over {} top-level elements", kMaxMaterialXElements),
            "a document of at most that many elements");
        return std::move(result_);
      }
      if (const char* name = node.attribute("name").value(); *name) nodes_.emplace(name, node);
    }
    std::size_t found = 0;
    for (const pugi::xml_node& node : root_.children()) {
      const std::string_view tag = node.name();
      if (tag == "surfacematerial") {
        ++found;
        import_surface_material(node);
      } else if (tag == "material") {
        ++found;
        import_legacy_material(node);
      } else if (tag == "xi:include") {
        // Safe (nothing outside the document is read), but its materials would vanish silently.
        result_.diagnostics.note(
            at(node), "xi:include",
            fmt::format("includes '{}', which matc does not read: materials defined there are not "
                        "imported",
                        node.attribute("href").value()),
            "give that document to matc as an input of its own");
      }
    }
    if (result_.diagnostics.has_errors()) {
      result_.materials.clear();
    } else if (result_.materials.empty()) {
      result_.diagnostics.error(
          locator_.whole_file(), "",
          found == 0 ? "the document holds no material (<surfacematerial> or <material>)"
                     : "none of its materials is a metal matc imports (see above)",
          "a standard_surface or open_pbr_surface material with metalness above 0");
    }
    return std::move(result_);
  }

 private:
  SourceLocation at(const pugi::xml_node& node) const {
    // pugixml gives the offset of the element's name; diagnostics point at its '<'.
    const std::ptrdiff_t offset = node.offset_debug();
    return offset < 1 ? locator_.whole_file() : locator_.at(static_cast<std::size_t>(offset - 1));
  }

  void check_version() {
    const std::string_view version = root_.attribute("version").value();
    if (version.empty()) return;
    for (const std::string_view known : {"1.36", "1.37", "1.38", "1.39"})
      if (version == known) return;
    result_.diagnostics.warning(at(root_), "version",
                                fmt::format("MaterialX {} is not a version matc knows", version),
                                "1.36 to 1.39; read as 1.39");
  }

  bool read_document_space() {
    const pugi::xml_attribute attribute = root_.attribute("colorspace");
    if (attribute.empty()) return true;
    const auto space = linear_space_of(attribute.value(), root_);
    if (!space) return false;
    document_space_ = *space;
    return true;
  }

  // The linear space a colorspace name stands for (an encoded one: the space it decodes into).
  std::optional<ColorSpace> linear_space_of(std::string_view name, const pugi::xml_node& where) {
    if (const auto space = find_color_space(name)) return space;
    if (const auto decoded = decode_color_value(name, 0.0)) return decoded->space;
    unknown_space(where, "colorspace", name);
    return std::nullopt;
  }

  void unknown_space(const pugi::xml_node& where, const std::string& field, std::string_view name) {
    result_.diagnostics.error(at(where), field, fmt::format("unknown colour space '{}'", name),
                              "one of " + color_space_names() +
                                  ", or an encoded srgb_texture, g22_rec709, g18_rec709, g22_ap1, "
                                  "g18_ap1, srgb_displayp3");
  }

  // The colorspace in force at `node`: its own attribute, else its nearest ancestor's.
  std::string colorspace_at(pugi::xml_node node) const {
    for (; node; node = node.parent()) {
      const pugi::xml_attribute attribute = node.attribute("colorspace");
      if (!attribute.empty()) return attribute.value();
    }
    return std::string(color_space_name(kDefaultColorSpace));
  }

  void import_surface_material(const pugi::xml_node& material) {
    const pugi::xml_node input = material.find_child_by_attribute("input", "name", "surfaceshader");
    const std::string name = material.attribute("name").value();
    if (!input) {
      result_.diagnostics.note(at(material), name, "has no surfaceshader input; skipped");
      return;
    }
    const std::string shader_name = input.attribute("nodename").value();
    const auto shader = nodes_.find(shader_name);
    if (shader_name.empty() || shader == nodes_.end()) {
      result_.diagnostics.error(
          at(input), name + ".surfaceshader",
          shader_name.empty()
              ? "names no node (nodename is missing)"
              : fmt::format("names node '{}', which the document does not hold", shader_name),
          "the name of a shader node at the top level of the document");
      return;
    }
    import_material({material, shader->second, shader->second.name(), "input"});
  }

  void import_legacy_material(const pugi::xml_node& material) {
    const pugi::xml_node shaderref = material.child("shaderref");
    const std::string name = material.attribute("name").value();
    if (!shaderref) {
      result_.diagnostics.note(at(material), name, "has no <shaderref>; skipped");
      return;
    }
    std::string model = shaderref.attribute("node").value();
    if (model.empty()) {
      // 1.37 may name the node definition instead: ND_<node>_surfaceshader.
      const std::string_view nodedef = shaderref.attribute("nodedef").value();
      for (const ShadingModel* known : {&kStandardSurface, &kOpenPbrSurface}) {
        if (nodedef == fmt::format("ND_{}_surfaceshader", known->node)) model = known->node;
      }
    }
    import_material({material, shaderref, model, "bindinput"});
  }

  struct InputValue {
    Rgb value{};
    bool given = false;  // false: the specification's default
    SourceLocation location;
  };

  // Reads one input of the shader, or its default. Returns nullopt after reporting an error, or
  // after a warning when the input is connected (`connected` is then set).
  std::optional<InputValue> read_input(const SurfaceMaterial& surface, const InputSpec& spec,
                                       const std::string& material_name, bool& connected) {
    const pugi::xml_node input =
        surface.shader.find_child_by_attribute(surface.input_tag, "name", spec.name.data());
    InputValue result;
    result.value = spec.default_value;
    result.location = at(surface.material);
    if (!input) return result;
    result.location = at(input);
    const std::string field = fmt::format("{}.{}", material_name, spec.name);
    if (is_connected(input)) {
      connected = true;
      result_.diagnostics.warning(result.location, field, describe_connection(input),
                                  connection_advice(input, surface, spec));
      return std::nullopt;
    }
    const std::string_view declared = input.attribute("type").value();
    if (!declared.empty() && declared != type_name(spec.type)) {
      result_.diagnostics.error(
          result.location, field, fmt::format("has type '{}'", declared),
          fmt::format("{} declares {} a {}", surface.model, spec.name, type_name(spec.type)));
      return std::nullopt;
    }
    const auto parsed = parse_value(input.attribute("value").value(), spec.type);
    if (!parsed) {
      result_.diagnostics.error(result.location, field,
                                fmt::format("value '{}' is not a {}",
                                            input.attribute("value").value(), type_name(spec.type)),
                                spec.type == ValueType::float1
                                    ? "one finite number"
                                    : "three finite numbers separated by commas");
      return std::nullopt;
    }
    result.value = *parsed;
    result.given = true;
    if (spec.type == ValueType::color3) {
      if (!convert_color(result.value, input, field)) return std::nullopt;
    }
    return result;
  }

  // Decodes an encoded colour and converts it into the document's working space.
  bool convert_color(Rgb& value, const pugi::xml_node& input, const std::string& field) {
    const std::string space_name = colorspace_at(input);
    ColorSpace space = document_space_;
    if (const auto linear = find_color_space(space_name)) {
      space = *linear;
    } else if (is_encoded_color_space(space_name)) {
      for (double& channel : value) {
        const DecodedColor decoded = *decode_color_value(space_name, channel);
        channel = decoded.value;
        space = decoded.space;
      }
    } else {
      unknown_space(input, field, space_name);
      return false;
    }
    if (space != document_space_) value = multiply(rgb_to_rgb(space, document_space_), value);
    return true;
  }

  // Whether a not-carried input's value leaves the look unchanged: a float, a color3 or a
  // boolean equal to `neutral` in every component.
  static bool is_neutral(std::string_view text, double neutral) {
    if (text == "false" || text == "true") return (text == "true" ? 1.0 : 0.0) == neutral;
    for (const ValueType type : {ValueType::float1, ValueType::color3}) {
      if (const auto value = parse_value(text, type))
        return std::ranges::all_of(*value, [neutral](double v) { return v == neutral; });
    }
    return false;
  }

  static std::optional<Rgb> parse_value(std::string_view text, ValueType type) {
    std::array<double, 3> values{};
    std::size_t count = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
      std::size_t end = text.find(',', start);
      if (end == std::string_view::npos) end = text.size();
      std::string_view item = text.substr(start, end - start);
      while (!item.empty() && std::isspace(static_cast<unsigned char>(item.front())))
        item.remove_prefix(1);
      while (!item.empty() && std::isspace(static_cast<unsigned char>(item.back())))
        item.remove_suffix(1);
      if (item.empty() || count == 3) return std::nullopt;
      if (item.front() == '+') item.remove_prefix(1);
      double value = 0.0;
      const auto [rest, error] = std::from_chars(item.data(), item.data() + item.size(), value);
      if (error != std::errc() || rest != item.data() + item.size() || !std::isfinite(value)) {
        return std::nullopt;
      }
      values[count++] = value;
      start = end + 1;
    }
    const std::size_t expected = type == ValueType::float1 ? 1 : 3;
    if (count != expected) return std::nullopt;
    return type == ValueType::float1 ? Rgb{values[0], values[0], values[0]}
                                     : Rgb{values[0], values[1], values[2]};
  }

  std::string describe_connection(const pugi::xml_node& input) const {
    std::string source;
    if (const char* graph = input.attribute("nodegraph").value(); *graph) {
      source = fmt::format("node graph '{}'", graph);
    } else if (const char* node = input.attribute("nodename").value(); *node) {
      source = fmt::format("node '{}'", node);
    } else {
      source = fmt::format("interface input '{}'", input.attribute("interfacename").value());
    }
    return fmt::format("is driven by {}, not a constant", source);
  }

  // The image file an input reads when it is a plain image read (directly, or the output of a
  // node graph that is one), else empty.
  std::string image_file(const pugi::xml_node& input) const {
    pugi::xml_node node;
    if (const char* graph_name = input.attribute("nodegraph").value(); *graph_name) {
      const auto graph = nodes_.find(graph_name);
      if (graph == nodes_.end()) return {};
      const char* output_name = input.attribute("output").value();
      pugi::xml_node output =
          *output_name ? graph->second.find_child_by_attribute("output", "name", output_name)
                       : graph->second.child("output");
      node = graph->second.find_child_by_attribute("name", output.attribute("nodename").value());
    } else if (const char* node_name = input.attribute("nodename").value(); *node_name) {
      const auto found = nodes_.find(node_name);
      if (found != nodes_.end()) node = found->second;
    }
    const std::string_view kind = node.name();
    if (kind != "image" && kind != "tiledimage") return {};
    return node.find_child_by_attribute("input", "name", "file").attribute("value").value();
  }

  std::string connection_advice(const pugi::xml_node& input, const SurfaceMaterial& surface,
                                const InputSpec& spec) const {
    const std::string file = image_file(input);
    const bool fresnel_input = spec.name != "specular_roughness";
    std::string advice = fresnel_input
                             ? "matc imports constant metals only, so this material is skipped"
                             : "the roughness is left out of the imported material";
    if (!file.empty() && fresnel_input && surface.model == kStandardSurface.node) {
      advice += fmt::format(
          "; it is a plain image read of '{}': `matc bake --reflectivity {} --edge-tint G` bakes "
          "it as a textured metal (docs/baking.md), with G = specular x specular_color and the "
          "map scaled by base if base is not 1",
          file, file);
    } else if (!file.empty() && fresnel_input) {
      advice += fmt::format(
          "; it is a plain image read of '{}', and `matc bake` does not bake F82-tint maps yet",
          file);
    }
    return advice;
  }

  void import_material(const SurfaceMaterial& surface) {
    const std::string element_name = surface.material.attribute("name").value();
    const ShadingModel* model = find_shading_model(surface.model);
    if (!model) {
      result_.diagnostics.note(
          at(surface.material), element_name,
          surface.model.empty()
              ? "names no shading model; skipped"
              : fmt::format("uses the shading model '{}', which matc does not import; skipped",
                            surface.model),
          "standard_surface or open_pbr_surface");
      return;
    }
    // A connected Fresnel input is warned about and leaves its value unset: the material is
    // skipped, since matc imports constant metals only.
    bool connected = false;
    const auto read = [&](const InputSpec& spec) {
      return read_input(surface, spec, element_name, connected);
    };
    const auto weight = read(model->weight);
    const auto color = read(model->color);
    const auto metalness = read(model->metalness);
    const auto edge_weight = read(model->edge_weight);
    const auto edge_color = read(model->edge_color);
    bool roughness_connected = false;
    const auto roughness = read_input(surface, model->roughness, element_name, roughness_connected);
    if (!weight || !color || !metalness || !edge_weight || !edge_color) return;
    if (!roughness && !roughness_connected) return;

    const double metal = metalness->value[0];
    const std::string metal_field = fmt::format("{}.{}", element_name, model->metalness.name);
    if (metal < 0.0 || metal > 1.0) {
      result_.diagnostics.error(metalness->location, metal_field,
                                fmt::format("{} is out of range", metal), "a number in [0, 1]");
      return;
    }
    if (metal == 0.0) {
      result_.diagnostics.note(
          at(surface.material), element_name,
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
    note_not_carried(surface, *model, element_name);

    Rgb f0{};
    Rgb edge{};
    for (std::size_t c = 0; c < 3; ++c) {
      f0[c] = weight->value[0] * color->value[c];
      edge[c] = model == &kStandardSurface ? edge_weight->value[0] * edge_color->value[c]
                                           : edge_color->value[c];
    }
    const double f0_limit = model == &kStandardSurface ? kMaxArtisticReflectivity : 1.0;
    clamp_channels(f0, 0.0, f0_limit, color->location, element_name,
                   model == &kStandardSurface ? "reflectivity (base x base_color)"
                                              : "F0 (base_weight x base_color)",
                   model == &kStandardSurface ? "as MaterialX's artistic_ior does: [0, 0.99]"
                                              : "OpenPBR's metal reflectance range [0, 1]");
    clamp_channels(edge, 0.0, 1.0, edge_color->location, element_name,
                   model == &kStandardSurface ? "edge tint (specular x specular_color)"
                                              : "tint (specular_color)",
                   "[0, 1], the range matc's model takes");
    if (model == &kOpenPbrSurface && edge_weight->given && edge_weight->value[0] != 1.0) {
      result_.diagnostics.note(
          edge_weight->location, fmt::format("{}.specular_weight", element_name),
          fmt::format("{} scales OpenPBR's metal Fresnel (min(1, weight x F)); matc compiles F "
                      "itself, so apply the weight in the engine",
                      edge_weight->value[0]));
    }

    ordered_json json;
    json["name"] = material_name(element_name, surface.material);
    json["description"] =
        fmt::format("Imported from {} (material '{}', {}{})",
                    std::filesystem::path(locator_.path()).filename().string(), element_name,
                    model->node, metal < 1.0 ? fmt::format(", metal lobe of {}", metal) : "");
    json["color_space"] = color_space_name(document_space_);
    const auto rgb = [](const Rgb& v) { return ordered_json::array({v[0], v[1], v[2]}); };
    if (model == &kStandardSurface) {
      json["artistic"] = {{"reflectivity", rgb(f0)}, {"edge_tint", rgb(edge)}};
    } else {
      json["f82_tint"] = {{"f0", rgb(f0)}, {"tint", rgb(edge)}};
    }
    if (roughness) json["roughness"] = roughness->value[0];
    if (json["name"].get<std::string>().empty()) return;  // a name clash, reported
    add_material(json, surface.material);
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

  void note_not_carried(const SurfaceMaterial& surface, const ShadingModel& model,
                        const std::string& material) {
    std::vector<std::string> given;
    for (const NotCarried& entry : model.not_carried) {
      const pugi::xml_node input =
          surface.shader.find_child_by_attribute(surface.input_tag, "name", entry.name.data());
      if (!input) continue;
      if (!is_connected(input) && is_neutral(input.attribute("value").value(), entry.neutral))
        continue;
      given.emplace_back(entry.name);
    }
    if (given.empty()) return;
    std::string list;
    for (const std::string& name : given)
      list += (list.empty() ? "" : ", ") + name;
    result_.diagnostics.note(at(surface.material), material,
                             fmt::format("not carried: {} (matc compiles the metal's Fresnel; "
                                         "docs/interchange.md lists what is left out and why)",
                                         list));
  }

  // The matc name for a material element: sanitised, and unique in the document ignoring case.
  // Empty after reporting a clash.
  std::string material_name(const std::string& element_name, const pugi::xml_node& material) {
    const std::string name = sanitized_material_name(element_name);
    if (name != element_name) {
      result_.diagnostics.note(at(material), element_name, fmt::format("imported as '{}'", name),
                               std::string(kMaterialNameRule));
    }
    std::string key = name;
    std::transform(key.begin(), key.end(), key.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const auto [first, inserted] = names_.emplace(key, FirstName{name, element_name, at(material)});
    if (!inserted) {
      result_.diagnostics.error(
          at(material), element_name,
          fmt::format("becomes '{}', which is '{}' (material '{}' at {}:{}) ignoring case", name,
                      first->second.name, first->second.element, first->second.location.line,
                      first->second.location.column),
          "material names that still differ after sanitising, ignoring case (they name files)");
      return {};
    }
    return name;
  }

  void add_material(const ordered_json& json, const pugi::xml_node& element) {
    ImportedMaterial imported;
    // Names and descriptions come from the document's bytes, which XML parsing does not check
    // for UTF-8: a bad byte becomes U+FFFD in the description (the name is ASCII by then).
    imported.json = json.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
    ParseResult parsed = parse_material(imported.json, locator_.path());
    if (!parsed.material) {
      // The importer checked every value; a refusal here is matc's bug, reported as such.
      result_.diagnostics.error(at(element), json["name"].get<std::string>(),
                                "the imported material does not validate (an importer bug)",
                                parsed.diagnostics.items().empty()
                                    ? std::string()
                                    : parsed.diagnostics.items().front().message);
      return;
    }
    imported.material = std::move(*parsed.material);
    imported.material.name_location = at(element);
    result_.materials.push_back(std::move(imported));
  }

  std::string_view text_;
  TextLocator locator_;
  pugi::xml_document document_;
  pugi::xml_node root_;
  ColorSpace document_space_ = kDefaultColorSpace;
  std::map<std::string, pugi::xml_node> nodes_;  // top-level elements by name
  struct FirstName {
    std::string name;     // as imported
    std::string element;  // as the document writes it
    SourceLocation location;
  };
  std::map<std::string, FirstName> names_;  // lowercase imported name -> its first use
  MaterialXImport result_;
};

}  // namespace

std::string sanitized_material_name(std::string_view name) {
  std::string out;
  for (const char c : name) {
    const bool keep =
        std::isalnum(static_cast<unsigned char>(c)) != 0 && static_cast<unsigned char>(c) < 0x80;
    const char next = keep ? c : '_';
    if (next == '_' && (out.empty() || out.back() == '_')) continue;
    out += next;
  }
  if (out.empty()) return "material";
  if (!std::isalpha(static_cast<unsigned char>(out.front()))) out = "m_" + out;
  if (out.size() > kMaxMaterialNameLength) out.resize(kMaxMaterialNameLength);
  return out;  // no "__": runs of '_' were folded, and leading ones dropped
}

bool is_materialx_path(std::string_view path) {
  if (path.size() < 5) return false;
  std::string extension(path.substr(path.size() - 5));
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".mtlx";
}

MaterialXImport import_materialx(std::string_view text, const std::string& path) {
  return Importer(text, path).run();
}

MaterialXImport read_materialx_file(const std::string& path, const FileLoader& loader) {
  const LoadedFile loaded = loader(path, kMaxMaterialXFileBytes);
  if (!loaded.bytes) {
    MaterialXImport result;
    result.diagnostics.error({path, 0, 0}, "", fmt::format("cannot read: {}", loaded.error),
                             "a MaterialX document of at most 16 MiB");
    return result;
  }
  return import_materialx(*loaded.bytes, path);
}

}  // namespace matc
