// A read XML document's elements and attributes (internal to the MaterialX importer), the same
// tree whichever library parsed it: pugixml in the native library (the reader MaterialX itself
// uses), rapidxml (header-only) in the WebAssembly one, where Debian has no pugixml source. Both
// adapters give pugixml's reading of a well-formed document: attribute values with references
// expanded and white space (tab, line feed, CR LF) turned into spaces; elements only (text,
// comments and processing instructions are dropped). `matc_xml_tree_fuzzer` holds the two to it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace matc {

struct XmlAttribute {
  std::string name;
  std::string value;
};

struct XmlElement {
  std::string name;
  std::size_t offset = 0;                // of the element's '<' in the text
  std::vector<XmlAttribute> attributes;  // in document order, a repeated name kept
  std::vector<const XmlElement*> children;
  const XmlElement* parent = nullptr;  // null for a top-level element

  // The value of the first attribute `name`; empty when there is none.
  std::string_view attribute(std::string_view attribute_name) const;
  bool has_attribute(std::string_view attribute_name) const;
  // The first child element named `tag`, or null.
  const XmlElement* child(std::string_view tag) const;
  // The first child element (named `tag`, any name when empty) whose attribute `attribute_name`
  // is `value`.
  const XmlElement* child_with(std::string_view tag, std::string_view attribute_name,
                               std::string_view value) const;
};

struct XmlTree {
  std::deque<XmlElement> elements;           // owns every element (addresses stay put)
  std::vector<const XmlElement*> top_level;  // elements outside any other, in order
};

// What is wrong with a document, where; no input text in `message` but through echoed().
struct XmlProblem {
  std::size_t offset;  // byte offset in the text
  std::string message;
};

// The deepest element nesting read: MaterialX documents nest a few levels, and the tree is built
// (and rapidxml parses) by recursion.
inline constexpr std::size_t kMaxXmlDepth = 256;

// XML's white space, and pugixml's name characters (its ct_start_symbol, ct_symbol): what both
// readers' checks take a name and the space between attributes to be.
bool is_xml_space(char c);
bool starts_xml_name(char c);
bool continues_xml_name(char c);

enum class XmlLibrary { pugixml, rapidxml };

// The problem both readers report for text outside the root element.
inline constexpr std::string_view kXmlTextOutsideRoot = "text outside the root element";

// The library this build reads MaterialX with: pugixml natively, rapidxml in WebAssembly (the
// native library has both, so tests and the fuzzer compare them).
XmlLibrary default_xml_library();

// Where the markup opening at `text[at]` == '<' ends (past its closing delimiter), for the markup
// that holds no elements: comments, CDATA sections, processing instructions, declarations ("<!",
// up to the first '>'). npos when a tag opens there.
std::size_t end_of_other_markup(std::string_view text, std::size_t at);

// The end of the start tag opening at `text[at]` == '<' (past its '>'; the text's end when it has
// none), and whether the tag closes itself ("/>"), read as both libraries read a well-formed tag.
std::pair<std::size_t, bool> end_of_start_tag(std::string_view text, std::size_t at);

// The parse of `text` (UTF-8, already checked by find_xml_character_problem), or the first problem:
// nesting past kMaxXmlDepth, else what the library reports. Text outside the root element is a
// problem with both libraries (XML 1.0 allows only markup and white space there; rapidxml refuses
// it, pugixml would keep it), and so is a document with no element.
std::variant<XmlTree, XmlProblem> read_xml_tree(std::string_view text,
                                                XmlLibrary library = default_xml_library());

// Builds the tree of a library's parse depth first with a stack (no recursion, whatever the
// nesting): `roots` its top-level element nodes, `children(node, visit)` calls `visit` on a node's
// child element nodes in order, `fill(node, element)` sets an element's name, place and
// attributes. For the two libraries' adapters.
template <class Node, class Children, class Fill>
XmlTree build_xml_tree(const std::vector<Node>& roots, Children children, Fill fill) {
  XmlTree tree;
  std::vector<std::pair<Node, XmlElement*>> pending;
  const auto add = [&](const Node& node, XmlElement* parent) {
    XmlElement& element = tree.elements.emplace_back();
    fill(node, element);
    element.parent = parent;
    (parent ? parent->children : tree.top_level).push_back(&element);
    pending.emplace_back(node, &element);
  };
  for (const Node& root : roots)
    add(root, nullptr);
  std::reverse(pending.begin(), pending.end());
  while (!pending.empty()) {
    const Node node = pending.back().first;
    XmlElement* element = pending.back().second;
    pending.pop_back();
    const std::size_t first = pending.size();
    children(node, [&](const Node& child) { add(child, element); });
    std::reverse(pending.begin() + static_cast<std::ptrdiff_t>(first), pending.end());
  }
  return tree;
}

// The libraries' own parses (xml_tree_pugixml.cpp, xml_tree_rapidxml.cpp), for read_xml_tree.
std::variant<XmlTree, XmlProblem> parse_xml_with_pugixml(std::string_view text);
std::variant<XmlTree, XmlProblem> parse_xml_with_rapidxml(std::string_view text);

}  // namespace matc
