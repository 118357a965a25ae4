#include "materialx_document.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "base/number_text.h"
#include "material/materialx_import.h"
#include "xml_well_formed.h"

namespace matc {
namespace {

bool is_connected(const XmlElement& input) {
  for (const char* attribute : {"nodename", "nodegraph", "output", "interfacename"})
    if (input.has_attribute(attribute)) return true;
  return false;
}

}  // namespace

std::string_view materialx_type_name(MaterialXType type) {
  return type == MaterialXType::float1 ? "float" : "color3";
}

// As MaterialX's reference implementation reads a vector value (MaterialXCore/Value.cpp,
// stringToData: splitString(value, ARRAY_VALID_SEPARATORS), where the separators are ", "): any run
// of commas and spaces separates two numbers, and separators at either end are dropped, so
// "0.9, 0.6, 0.3", "0.9,0.6,0.3" and "0.9 0.6 0.3" are the same colour. Each number is read in
// full: where MaterialX's stream read would keep the prefix of "0.5abc", matc refuses it.
std::optional<Rgb> parse_materialx_value(std::string_view text, MaterialXType type) {
  constexpr std::string_view kSeparators = ", ";
  std::array<double, 3> values{};
  std::size_t count = 0;
  std::size_t start = text.find_first_not_of(kSeparators);
  while (start != std::string_view::npos) {
    std::size_t end = text.find_first_of(kSeparators, start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view item = text.substr(start, end - start);
    start = text.find_first_not_of(kSeparators, end);
    // The stream read skips leading white space of every kind (tabs, line breaks).
    while (!item.empty() && std::isspace(static_cast<unsigned char>(item.front())))
      item.remove_prefix(1);
    while (!item.empty() && std::isspace(static_cast<unsigned char>(item.back())))
      item.remove_suffix(1);
    if (item.empty()) continue;
    if (count == 3) return std::nullopt;
    const std::optional<double> value = parse_number(item);
    if (!value) return std::nullopt;
    values[count++] = *value;
  }
  const std::size_t expected = type == MaterialXType::float1 ? 1 : 3;
  if (count != expected) return std::nullopt;
  return type == MaterialXType::float1 ? Rgb{values[0], values[0], values[0]}
                                       : Rgb{values[0], values[1], values[2]};
}

MaterialXDocument::MaterialXDocument(std::string_view text, const std::string& path,
                                     Diagnostics& diagnostics)
    : text_(text), locator_(path, text), diagnostics_(diagnostics) {
  const std::string_view allowed = "a MaterialX document (XML 1.0, UTF-8)";
  if (const auto problem = find_xml_character_problem(text_)) {
    diagnostics_.error(locator_.at(problem->offset), "",
                       fmt::format("malformed XML: {}", problem->message), std::string(allowed));
    return;
  }
  auto parsed = read_xml_tree(text_);
  if (const auto* problem = std::get_if<XmlProblem>(&parsed)) {
    diagnostics_.error(locator_.at(problem->offset), "",
                       fmt::format("malformed XML: {}", problem->message), std::string(allowed));
    return;
  }
  tree_ = std::move(std::get<XmlTree>(parsed));  // read_xml_tree: at least one element
  if (const auto duplicate = find_duplicate_attribute(tree_)) {
    diagnostics_.error(at(*duplicate->element), "",
                       fmt::format("malformed XML: <{}> gives the attribute '{}' twice",
                                   echoed(duplicate->element->name), echoed(duplicate->name)),
                       "each attribute of an element at most once (XML 1.0 section 3.1)");
    return;
  }
  root_ = tree_.top_level.front();
  if (root_->name != "materialx") {
    diagnostics_.error(at(*root_), "", fmt::format("the root element is <{}>", echoed(root_->name)),
                       "a MaterialX document, whose root element is <materialx>");
    return;
  }
  check_version();
  if (!read_document_space()) return;
  std::size_t elements = 0;
  for (const XmlElement* element : root_->children) {
    if (++elements > kMaxMaterialXElements) {
      diagnostics_.error(
          at(*element), "",
          fmt::format("the document has over {} top-level elements", kMaxMaterialXElements),
          "a document of at most that many elements");
      return;
    }
    if (const std::string_view name = element->attribute("name"); !name.empty())
      nodes_.emplace(name, element);
  }
  readable_ = true;
}

SourceLocation MaterialXDocument::at(const XmlElement& element) const {
  return locator_.at(element.offset);
}

void MaterialXDocument::check_version() {
  const std::string_view version = root_->attribute("version");
  if (version.empty()) return;
  for (const std::string_view known : {"1.36", "1.37", "1.38", "1.39"})
    if (version == known) return;
  diagnostics_.warning(at(*root_), "version",
                       fmt::format("MaterialX {} is not a version matc knows", echoed(version)),
                       "1.36 to 1.39; read as 1.39");
}

bool MaterialXDocument::read_document_space() {
  if (!root_->has_attribute("colorspace")) return true;
  const auto space = linear_space_of(root_->attribute("colorspace"), *root_);
  if (!space) return false;
  space_ = *space;
  return true;
}

// The linear space a colorspace name stands for (an encoded one: the space it decodes into).
std::optional<ColorSpace> MaterialXDocument::linear_space_of(std::string_view name,
                                                             const XmlElement& where) {
  if (const auto space = find_color_space(name)) return space;
  if (const auto decoded = decode_color_value(name, 0.0)) return decoded->space;
  unknown_space(where, "colorspace", name);
  return std::nullopt;
}

void MaterialXDocument::unknown_space(const XmlElement& where, const std::string& field,
                                      std::string_view name) {
  diagnostics_.error(at(where), field, fmt::format("unknown colour space '{}'", echoed(name)),
                     "one of " + color_space_names() +
                         ", or an encoded srgb_texture, g22_rec709, g18_rec709, g22_ap1, "
                         "g18_ap1, srgb_displayp3");
}

std::size_t MaterialXDocument::visit_materials(
    const std::function<void(const MaterialXShader&)>& visit) {
  std::size_t found = 0;
  for (const XmlElement* element : root_->children) {
    const std::string_view tag = element->name;
    const std::string name(element->attribute("name"));
    if (tag == "surfacematerial") {
      ++found;
      const XmlElement* input = element->child_with("input", "name", "surfaceshader");
      if (!input) {
        diagnostics_.note(at(*element), name, "has no surfaceshader input; skipped");
        continue;
      }
      const std::string_view shader_name = input->attribute("nodename");
      const auto shader = nodes_.find(shader_name);
      if (shader_name.empty() || shader == nodes_.end()) {
        diagnostics_.error(at(*input), name + ".surfaceshader",
                           shader_name.empty()
                               ? "names no node (nodename is missing)"
                               : fmt::format("names node '{}', which the document does not hold",
                                             echoed(shader_name)),
                           "the name of a shader node at the top level of the document");
        continue;
      }
      visit({element, shader->second, shader->second->name, "input"});
    } else if (tag == "material") {
      ++found;
      const XmlElement* shaderref = element->child("shaderref");
      if (!shaderref) {
        diagnostics_.note(at(*element), name, "has no <shaderref>; skipped");
        continue;
      }
      std::string model(shaderref->attribute("node"));
      const std::string_view nodedef = shaderref->attribute("nodedef");
      // 1.37 may name the node definition instead: ND_<node>_surfaceshader.
      if (model.empty() && nodedef.starts_with("ND_") && nodedef.ends_with("_surfaceshader"))
        model = nodedef.substr(3, nodedef.size() - 3 - std::string_view("_surfaceshader").size());
      visit({element, shaderref, model, "bindinput"});
    } else if (tag == "xi:include") {
      // Safe (nothing outside the document is read), but its materials would vanish silently.
      diagnostics_.note(
          at(*element), "xi:include",
          fmt::format("includes '{}', which matc does not read: materials defined there are not "
                      "imported",
                      echoed(element->attribute("href"), 128)),
          "give that document to matc as an input of its own");
    }
  }
  return found;
}

MaterialXInput MaterialXDocument::read_input(const MaterialXShader& shader, std::string_view name,
                                             MaterialXType type, const std::string& field) {
  const XmlElement* found = shader.node->child_with(shader.input_tag, "name", name);
  MaterialXInput result;
  result.location = at(*shader.material);
  if (!found) return result;
  const XmlElement& input = *found;
  result.location = at(input);
  if (is_connected(input)) {
    result.state = MaterialXInput::State::connected;
    result.connection = describe_connection(input);
    result.image_file = image_file(input);
    return result;
  }
  result.state = MaterialXInput::State::invalid;
  const std::string_view declared = input.attribute("type");
  if (!declared.empty() && declared != materialx_type_name(type)) {
    diagnostics_.error(
        result.location, field, fmt::format("has type '{}'", echoed(declared)),
        fmt::format("{} declares {} a {}", shader.model, name, materialx_type_name(type)));
    return result;
  }
  const auto parsed = parse_materialx_value(input.attribute("value"), type);
  if (!parsed) {
    diagnostics_.error(result.location, field,
                       fmt::format("value '{}' is not a {}", echoed(input.attribute("value")),
                                   materialx_type_name(type)),
                       type == MaterialXType::float1
                           ? "one finite number"
                           : "three finite numbers separated by commas or spaces");
    return result;
  }
  result.value = *parsed;
  if (type == MaterialXType::color3 && !convert_color(result.value, input, field)) return result;
  result.state = MaterialXInput::State::value;
  return result;
}

bool MaterialXDocument::is_neutral(const MaterialXShader& shader, std::string_view name,
                                   double neutral) const {
  const XmlElement* input = shader.node->child_with(shader.input_tag, "name", name);
  if (!input) return true;
  if (is_connected(*input)) return false;
  const std::string_view text = input->attribute("value");
  if (text == "false" || text == "true") return (text == "true" ? 1.0 : 0.0) == neutral;
  for (const MaterialXType type : {MaterialXType::float1, MaterialXType::color3}) {
    if (const auto value = parse_materialx_value(text, type))
      return std::all_of(value->begin(), value->end(),
                         [neutral](double v) { return v == neutral; });
  }
  return false;
}

// Decodes an encoded colour and converts it into the document's working space.
bool MaterialXDocument::convert_color(Rgb& value, const XmlElement& input,
                                      const std::string& field) {
  // The colorspace in force at the input: its own attribute, else its nearest ancestor's.
  std::string space_name(color_space_name(kDefaultColorSpace));
  for (const XmlElement* element = &input; element; element = element->parent) {
    if (element->has_attribute("colorspace")) {
      space_name = element->attribute("colorspace");
      break;
    }
  }
  ColorSpace space = space_;
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
  if (space != space_) value = multiply(rgb_to_rgb(space, space_), value);
  return true;
}

std::string MaterialXDocument::describe_connection(const XmlElement& input) const {
  std::string source;
  if (const std::string_view graph = input.attribute("nodegraph"); !graph.empty()) {
    source = fmt::format("node graph '{}'", echoed(graph));
  } else if (const std::string_view node = input.attribute("nodename"); !node.empty()) {
    source = fmt::format("node '{}'", echoed(node));
  } else {
    source = fmt::format("interface input '{}'", echoed(input.attribute("interfacename")));
  }
  return fmt::format("is driven by {}, not a constant", source);
}

// The image file an input reads when it is a plain image read (directly, or the output of a node
// graph that is one), else empty.
std::string MaterialXDocument::image_file(const XmlElement& input) const {
  const XmlElement* node = nullptr;
  if (const std::string_view graph_name = input.attribute("nodegraph"); !graph_name.empty()) {
    const auto graph = nodes_.find(graph_name);
    if (graph == nodes_.end()) return {};
    const std::string_view output_name = input.attribute("output");
    const XmlElement* output = output_name.empty()
                                   ? graph->second->child("output")
                                   : graph->second->child_with("output", "name", output_name);
    node = graph->second->child_with("", "name", output ? output->attribute("nodename") : "");
  } else if (const std::string_view node_name = input.attribute("nodename"); !node_name.empty()) {
    const auto found = nodes_.find(node_name);
    if (found != nodes_.end()) node = found->second;
  }
  if (!node || (node->name != "image" && node->name != "tiledimage")) return {};
  const XmlElement* file = node->child_with("input", "name", "file");
  return file ? std::string(file->attribute("value")) : std::string();
}

}  // namespace matc
