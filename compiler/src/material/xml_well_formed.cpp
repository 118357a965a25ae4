#include "xml_well_formed.h"

#include <cctype>
#include <charconv>
#include <set>
#include <vector>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "base/utf8.h"

namespace matc {
namespace {

// XML 1.0, production [2] Char.
bool is_xml_char(char32_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) ||
         (c >= 0xE000 && c <= 0xFFFD) || (c >= 0x10000 && c <= 0x10FFFF);
}

// The problem with the character reference at `text[at]` ("&#..."), if any. Its digits are read
// whole, however many (pugixml expands "&#0000000000001;" to U+0001, and wraps values past 32
// bits), and scanned once, so a document of unterminated references stays linear.
std::optional<XmlProblem> check_character_reference(std::string_view text, std::size_t at) {
  std::size_t end = at + 2;
  const bool hexadecimal = end < text.size() && text[end] == 'x';
  if (hexadecimal) ++end;
  const std::size_t first = end;
  const auto is_digit = [hexadecimal](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) ||
           (hexadecimal && std::isxdigit(static_cast<unsigned char>(c)));
  };
  while (end < text.size() && is_digit(text[end]))
    ++end;
  // Not a reference pugixml expands (it keeps the text, or reports it): nothing to check.
  if (end == first || end == text.size() || text[end] != ';') return std::nullopt;
  std::uint32_t value = 0;
  const auto [last, error] =
      std::from_chars(text.data() + first, text.data() + end, value, hexadecimal ? 16 : 10);
  const bool past_unicode = error == std::errc::result_out_of_range;
  if (!past_unicode && is_xml_char(value)) return std::nullopt;
  const std::string reference = echoed(text.substr(at, end - at + 1));
  return XmlProblem{at, past_unicode ? fmt::format("the character reference '{}' names no "
                                                   "character (past U+10FFFF), which XML 1.0 "
                                                   "does not allow (section 4.1, Legal Character)",
                                                   reference)
                                     : fmt::format("the character reference '{}' names U+{:04X}, "
                                                   "which XML 1.0 does not allow (section 4.1, "
                                                   "Legal Character)",
                                                   reference, value)};
}

}  // namespace

std::optional<XmlProblem> find_xml_character_problem(std::string_view text) {
  // Every character, markup and literal sections included, must be an XML Char in UTF-8.
  for (std::size_t at = 0; at < text.size();) {
    char32_t c = 0;
    const std::size_t length = utf8_sequence(text, at, c);
    if (length == 0) {
      return XmlProblem{at, fmt::format("byte 0x{:02X} is not UTF-8 (the document's encoding)",
                                        static_cast<unsigned char>(text[at]))};
    }
    if (!is_xml_char(c)) {
      return XmlProblem{at, c == 0 ? std::string("a NUL byte, which XML 1.0 does not allow")
                                   : fmt::format("the character U+{:04X}, which XML 1.0 does not "
                                                 "allow (section 2.2, Characters)",
                                                 static_cast<std::uint32_t>(c))};
    }
    at += length;
  }
  // References are expanded everywhere but in comments, CDATA, processing instructions and
  // declarations, whose openings inside a start tag (in an attribute's value) are text.
  std::size_t tag_end = 0;  // the end of the start tag `at` is in, when it is in one
  for (std::size_t at = 0; at < text.size();) {
    if (text[at] == '<' && at >= tag_end) {
      if (const std::size_t end = end_of_other_markup(text, at); end != std::string_view::npos) {
        at = end;
        continue;
      }
      if (at + 1 < text.size() && text[at + 1] != '/') tag_end = end_of_start_tag(text, at).first;
    }
    if (text.substr(at).starts_with("&#")) {
      if (auto problem = check_character_reference(text, at)) return problem;
    }
    ++at;
  }
  return std::nullopt;
}

std::optional<DuplicateAttribute> find_duplicate_attribute(const XmlTree& tree) {
  std::vector<const XmlElement*> pending(tree.top_level.rbegin(), tree.top_level.rend());
  while (!pending.empty()) {
    const XmlElement* element = pending.back();
    pending.pop_back();
    std::set<std::string_view> names;
    for (const XmlAttribute& attribute : element->attributes) {
      if (!names.insert(attribute.name).second) return DuplicateAttribute{element, attribute.name};
    }
    // Children pushed last-first, so elements are visited in document order.
    pending.insert(pending.end(), element->children.rbegin(), element->children.rend());
  }
  return std::nullopt;
}

}  // namespace matc
