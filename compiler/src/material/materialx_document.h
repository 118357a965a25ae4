// Reading a MaterialX document (internal to the importer): the XML, its root, version and colour
// space, its top-level elements by name, every material with the shader node it uses in either
// form (1.38's <surfacematerial> and a shader node, 1.37's <material> and <shaderref>), and the
// constant values of a shader's inputs in the document's colour space. What the inputs mean is
// the shading models' (materialx_models.h).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostics.h"
#include "optics/color_space.h"
#include "xml_tree.h"

namespace matc {

enum class MaterialXType { float1, color3 };

// A material element and the shader it uses.
struct MaterialXShader {
  const XmlElement* material;  // <surfacematerial> or <material>
  const XmlElement* node;      // the shader node, or the <shaderref>
  std::string model;           // the shading model's node name (empty when none is named)
  const char* input_tag;       // "input" or "bindinput"
  std::string name() const { return std::string(material->attribute("name")); }
};

// One input of a shader as read.
struct MaterialXInput {
  enum class State { absent, value, connected, invalid } state = State::absent;
  Rgb value{};  // with State::value; a float in every channel
  SourceLocation location;
  std::string connection;  // with State::connected: "is driven by node 'x', not a constant"
  std::string image_file;  // with State::connected: the file of a plain image read, if it is one
};

class MaterialXDocument {
 public:
  // Parses and checks the document; problems go to `diagnostics`.
  MaterialXDocument(std::string_view text, const std::string& path, Diagnostics& diagnostics);

  // Whether the document is one whose materials can be read.
  bool readable() const { return readable_; }
  const std::string& path() const { return locator_.path(); }
  ColorSpace color_space() const { return space_; }

  // Calls `visit` for every material element with a shader, in document order; elements without
  // one (and xi:include elements, which are not followed) are reported in between. Returns how
  // many material elements there are, shader or not.
  std::size_t visit_materials(const std::function<void(const MaterialXShader&)>& visit);

  // The input `name` of the shader as a constant of `type`, converted into the document's space
  // when a colour. Type, value and colour-space errors are reported (State::invalid) under `field`.
  MaterialXInput read_input(const MaterialXShader& shader, std::string_view name,
                            MaterialXType type, const std::string& field);
  // Whether the input is absent, or a constant equal to `neutral` in every component (booleans
  // read as 0 and 1).
  bool is_neutral(const MaterialXShader& shader, std::string_view name, double neutral) const;

  SourceLocation at(const XmlElement& element) const;
  SourceLocation whole_file() const { return locator_.whole_file(); }

 private:
  void check_version();
  bool read_document_space();
  std::optional<ColorSpace> linear_space_of(std::string_view name, const XmlElement& where);
  void unknown_space(const XmlElement& where, const std::string& field, std::string_view name);
  bool convert_color(Rgb& value, const XmlElement& input, const std::string& field);
  std::string describe_connection(const XmlElement& input) const;
  std::string image_file(const XmlElement& input) const;

  std::string_view text_;
  TextLocator locator_;
  Diagnostics& diagnostics_;
  XmlTree tree_;
  const XmlElement* root_ = nullptr;
  ColorSpace space_ = kDefaultColorSpace;
  std::map<std::string, const XmlElement*, std::less<>> nodes_;  // top-level elements by name
  bool readable_ = false;
};

// "float" or "color3".
std::string_view materialx_type_name(MaterialXType type);

// A constant's text as MaterialX reads it: one number (float) or three, separated by any run of
// commas and spaces.
std::optional<Rgb> parse_materialx_value(std::string_view text, MaterialXType type);

}  // namespace matc
