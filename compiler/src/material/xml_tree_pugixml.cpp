// The XML tree read by pugixml: the native library's reader, as MaterialX's own.
#include <algorithm>
#include <utility>

#include <pugixml.hpp>

#include "xml_tree.h"

namespace matc {

std::variant<XmlTree, XmlProblem> parse_xml_with_pugixml(std::string_view text) {
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(
      text.data(), text.size(), pugi::parse_default | pugi::parse_trim_pcdata, pugi::encoding_utf8);
  if (!parsed) {
    return XmlProblem{static_cast<std::size_t>(std::max<std::ptrdiff_t>(parsed.offset, 0)),
                      parsed.description()};
  }
  std::vector<pugi::xml_node> roots;
  for (const pugi::xml_node& node : document.children())
    if (node.type() == pugi::node_element) roots.push_back(node);
  return build_xml_tree(
      roots,
      [](const pugi::xml_node& node, const auto& visit) {
        for (const pugi::xml_node& child : node.children())
          if (child.type() == pugi::node_element) visit(child);
      },
      [](const pugi::xml_node& node, XmlElement& element) {
        element.name = node.name();
        // pugixml gives the offset of the element's name; the element starts at its '<'.
        element.offset =
            static_cast<std::size_t>(std::max<std::ptrdiff_t>(node.offset_debug() - 1, 0));
        for (const pugi::xml_attribute& attribute : node.attributes())
          element.attributes.push_back({attribute.name(), attribute.value()});
      });
}

}  // namespace matc
