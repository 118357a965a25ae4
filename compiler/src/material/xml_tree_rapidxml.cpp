// The XML tree read by rapidxml: the WebAssembly library's reader (Debian ships pugixml compiled
// only, rapidxml as a header). rapidxml leaves attribute values as written here (non-destructive
// parse), and they are expanded as pugixml expands them, so both readings give the same tree.
#include <algorithm>
#include <cstdint>
#include <exception>
#include <optional>
#include <vector>

#include <rapidxml/rapidxml.hpp>

#include "xml_tree.h"

namespace matc {
namespace {

void append_utf8(std::string& out, std::uint32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// Expands the reference at raw[at] == '&' as pugixml does (its parse_escapes): a character
// reference, or one of XML's five named ones; anything else stays as written, and reading goes on
// at the first character that does not fit. Returns where reading goes on.
std::size_t expand_reference(std::string_view raw, std::size_t at, std::string& out) {
  std::size_t end = at + 1;
  const auto next = [&] { return end < raw.size() ? raw[end] : '\0'; };
  if (next() == '#') {
    ++end;
    const bool hexadecimal = next() == 'x';
    if (hexadecimal) ++end;
    std::uint32_t value = 0;
    bool digits = false;
    for (;; ++end) {
      const char c = next();
      const unsigned decimal = static_cast<unsigned char>(c) - '0';
      const unsigned letter = (static_cast<unsigned char>(c) | ' ') - 'a';
      if (decimal <= 9) {
        value = value * (hexadecimal ? 16 : 10) + decimal;
      } else if (hexadecimal && letter <= 5) {
        value = value * 16 + letter + 10;
      } else if (c == ';' && digits) {
        append_utf8(out, value);
        return end + 1;
      } else {
        break;
      }
      digits = true;
    }
  } else {
    // A name matched whole is expanded; otherwise pugixml's matcher stops at the first character
    // that differs from every name.
    std::size_t matched = 0;
    for (const auto& [name, character] : {std::pair<std::string_view, char>{"amp;", '&'},
                                          {"apos;", '\''},
                                          {"gt;", '>'},
                                          {"lt;", '<'},
                                          {"quot;", '"'}}) {
      std::size_t same = 0;
      while (same < name.size() && end + same < raw.size() && raw[end + same] == name[same])
        ++same;
      if (same == name.size()) {
        out += character;
        return end + same;
      }
      matched = std::max(matched, same);
    }
    end += matched;
  }
  out += raw.substr(at, end - at);
  return end;
}

// An attribute value as pugixml reads it (parse_escapes, parse_wconv_attribute, parse_eol).
std::string attribute_value(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  for (std::size_t at = 0; at < raw.size();) {
    const char c = raw[at];
    if (c == '&') {
      const std::size_t before = out.size();
      at = expand_reference(raw, at, out);
      // pugixml's values are C strings: a NUL from "&#0;" ends one. (find_xml_character_problem
      // refuses that reference; this keeps the two readings equal regardless.) Only what this
      // reference appended is searched, so a value of many references stays linear.
      if (const std::size_t nul = out.find('\0', before); nul != std::string::npos) {
        out.resize(nul);
        return out;
      }
    } else if (c == '\r') {
      out += ' ';
      at += at + 1 < raw.size() && raw[at + 1] == '\n' ? 2 : 1;
    } else {
      out += c == '\n' || c == '\t' ? ' ' : c;
      ++at;
    }
  }
  return out;
}

// The first character of `name` past pugixml's name characters (rapidxml takes any character but
// white space and a few delimiters in a name, pugixml refuses the tag), or null.
const char* past_name(const char* name, std::size_t size) {
  if (size == 0 || !starts_xml_name(name[0])) return name;
  for (std::size_t i = 1; i < size; ++i)
    if (!continues_xml_name(name[i])) return name + i;
  return nullptr;
}

// What pugixml refuses in a start tag rapidxml read: a name outside its characters, an attribute
// not set off by white space. Its words, at its places.
std::optional<std::pair<const char*, const char*>> start_tag_problem(
    const rapidxml::xml_node<>* node) {
  if (const char* bad = past_name(node->name(), node->name_size())) {
    return std::pair{bad, bad == node->name() ? "Could not determine tag type"
                                              : "Error parsing start element tag"};
  }
  for (const rapidxml::xml_attribute<>* attribute = node->first_attribute(); attribute;
       attribute = attribute->next_attribute()) {
    const char* name = attribute->name();
    if (!is_xml_space(name[-1]) || !starts_xml_name(name[0]))
      return std::pair{name, "Error parsing start element tag"};
    if (const char* bad = past_name(name, attribute->name_size()))
      return std::pair{bad + 1, "Error parsing element attribute"};
    // The value's closing quote is followed by white space or the tag's end.
    const char* after = attribute->value() + attribute->value_size() + 1;
    if (!is_xml_space(*after) && *after != '/' && *after != '>')
      return std::pair{after, "Error parsing element attribute"};
  }
  return std::nullopt;
}

}  // namespace

std::variant<XmlTree, XmlProblem> parse_xml_with_rapidxml(std::string_view text) {
  std::vector<char> buffer(text.begin(), text.end());
  buffer.push_back('\0');
  rapidxml::xml_document<> document;
  try {
    document.parse<rapidxml::parse_non_destructive | rapidxml::parse_validate_closing_tags>(
        buffer.data());
  } catch (const rapidxml::parse_error& error) {
    const char* where = error.where<char>();
    const bool inside = where >= buffer.data() && where < buffer.data() + buffer.size();
    XmlProblem problem{inside ? static_cast<std::size_t>(where - buffer.data()) : text.size(),
                       error.what()};
    // The commonest slip in a hand-edited document said in pugixml's words, at its place (the
    // end tag's name), so both builds report it alike.
    if (problem.message == std::string_view("expected <")) {
      problem.message = kXmlTextOutsideRoot;  // rapidxml says so only outside the root element
    } else if (problem.message == std::string_view("invalid closing tag name")) {
      if (const std::size_t end_tag = text.rfind("</", problem.offset);
          end_tag != std::string_view::npos) {
        problem = {end_tag + 2, "Start-end tags mismatch"};
      }
    }
    return problem;
  }
  // A CDATA section beside the root element, which rapidxml keeps.
  for (const rapidxml::xml_node<>* node = document.first_node(); node;
       node = node->next_sibling()) {
    if (node->type() == rapidxml::node_cdata) {
      return XmlProblem{static_cast<std::size_t>(node->value() - buffer.data()),
                        std::string(kXmlTextOutsideRoot)};
    }
  }
  using Node = const rapidxml::xml_node<>*;
  std::vector<Node> roots;
  for (Node node = document.first_node(); node; node = node->next_sibling())
    if (node->type() == rapidxml::node_element) roots.push_back(node);
  std::optional<XmlProblem> refused;
  XmlTree tree = build_xml_tree(
      roots,
      [](Node node, const auto& visit) {
        for (Node child = node->first_node(); child; child = child->next_sibling())
          if (child->type() == rapidxml::node_element) visit(child);
      },
      [&](Node node, XmlElement& element) {
        if (const auto problem = start_tag_problem(node); problem && !refused) {
          refused =
              XmlProblem{static_cast<std::size_t>(problem->first - buffer.data()), problem->second};
        }
        element.name.assign(node->name(), node->name_size());
        // The name follows the element's '<'.
        element.offset = static_cast<std::size_t>(node->name() - buffer.data()) - 1;
        for (const rapidxml::xml_attribute<>* attribute = node->first_attribute(); attribute;
             attribute = attribute->next_attribute()) {
          element.attributes.push_back(
              {std::string(attribute->name(), attribute->name_size()),
               attribute_value({attribute->value(), attribute->value_size()})});
        }
      });
  if (refused) return *refused;
  return tree;
}

}  // namespace matc
