// What XML 1.0 requires of a document and neither pugixml nor rapidxml checks (internal to the
// MaterialX importer): both read a NUL byte as the end of the text, pass control bytes, bytes
// that are not UTF-8 and character references to characters XML forbids (&#1;), and keep an
// attribute given twice. Expat and libxml2 refuse each of these as not well-formed; so does matc.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "xml_tree.h"

namespace matc {

// The first byte-level problem in `text`: a byte XML's Char production excludes (raw, or named by
// a character reference outside comments, CDATA sections and processing instructions), or bytes
// that are not UTF-8.
std::optional<XmlProblem> find_xml_character_problem(std::string_view text);

// The first element, in document order, that gives one attribute twice (XML 1.0 section 3.1,
// "Unique Att Spec"), with the attribute's name.
struct DuplicateAttribute {
  const XmlElement* element;
  std::string name;
};
std::optional<DuplicateAttribute> find_duplicate_attribute(const XmlTree& tree);

}  // namespace matc
