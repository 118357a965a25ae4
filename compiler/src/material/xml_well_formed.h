// What XML 1.0 requires of a document and pugixml does not check (internal to the MaterialX
// importer): pugixml reads a NUL byte as the end of the text, passes control bytes, bytes that
// are not UTF-8 and character references to characters XML forbids (&#1;), and keeps an attribute
// given twice. Expat and libxml2 refuse each of these as not well-formed; so does matc.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include <pugixml.hpp>

namespace matc {

struct XmlProblem {
  std::size_t offset;   // byte offset in the text
  std::string message;  // what is wrong, with no input text echoed raw
};

// The first byte-level problem in `text`: a byte XML's Char production excludes (raw, or named by
// a character reference outside comments, CDATA sections and processing instructions), or bytes
// that are not UTF-8.
std::optional<XmlProblem> find_xml_character_problem(std::string_view text);

// The first element, in document order, that gives one attribute twice (XML 1.0 section 3.1,
// "Unique Att Spec"), with the attribute's name.
struct DuplicateAttribute {
  pugi::xml_node element;
  std::string name;
};
std::optional<DuplicateAttribute> find_duplicate_attribute(const pugi::xml_node& root);

}  // namespace matc
