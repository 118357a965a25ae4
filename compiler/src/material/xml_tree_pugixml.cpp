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
  XmlTree tree;
  // Depth first with a stack of (pugixml node, the element it becomes): no recursion.
  std::vector<std::pair<pugi::xml_node, XmlElement*>> pending;
  const auto add = [&](const pugi::xml_node& node, XmlElement* parent) {
    XmlElement& element = tree.elements.emplace_back();
    element.name = node.name();
    // pugixml gives the offset of the element's name; the element starts at its '<'.
    element.offset = static_cast<std::size_t>(std::max<std::ptrdiff_t>(node.offset_debug() - 1, 0));
    for (const pugi::xml_attribute& attribute : node.attributes())
      element.attributes.push_back({attribute.name(), attribute.value()});
    element.parent = parent;
    if (parent) {
      parent->children.push_back(&element);
    } else {
      tree.top_level.push_back(&element);
    }
    pending.emplace_back(node, &element);
  };
  for (const pugi::xml_node& node : document.children())
    if (node.type() == pugi::node_element) add(node, nullptr);
  std::reverse(pending.begin(), pending.end());
  while (!pending.empty()) {
    const auto [node, element] = pending.back();
    pending.pop_back();
    const std::size_t first = pending.size();
    for (const pugi::xml_node& child : node.children())
      if (child.type() == pugi::node_element) add(child, element);
    std::reverse(pending.begin() + static_cast<std::ptrdiff_t>(first), pending.end());
  }
  return tree;
}

}  // namespace matc
