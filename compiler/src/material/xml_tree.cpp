#include "xml_tree.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

namespace matc {

bool is_xml_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool starts_xml_name(char c) {
  const auto byte = static_cast<unsigned char>(c);
  return byte >= 0x80 || std::isalpha(byte) || c == '_' || c == ':';
}

bool continues_xml_name(char c) {
  return starts_xml_name(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
}

std::size_t end_of_other_markup(std::string_view text, std::size_t at) {
  const std::string_view rest = text.substr(at);
  for (const auto& [open, close] : {std::pair<std::string_view, std::string_view>{"<!--", "-->"},
                                    {"<![CDATA[", "]]>"},
                                    {"<?", "?>"},
                                    {"<!", ">"}}) {
    if (!rest.starts_with(open)) continue;
    const std::size_t end = text.find(close, at + open.size());
    return end == std::string_view::npos ? text.size() : end + close.size();
  }
  return std::string_view::npos;
}

// A quote opens a value only after '=' (with white space between), as in both libraries, so an
// attribute name holding a quote (which rapidxml accepts) cannot hide the tags after it.
std::pair<std::size_t, bool> end_of_start_tag(std::string_view text, std::size_t at) {
  char last = 0;  // the last character outside white space and values
  for (std::size_t i = at + 1; i < text.size(); ++i) {
    const char c = text[i];
    if ((c == '"' || c == '\'') && last == '=') {
      const std::size_t close = text.find(c, i + 1);
      if (close == std::string_view::npos) return {text.size(), false};
      i = close;
      last = c;
    } else if (c == '>') {
      return {i + 1, last == '/'};
    } else if (!is_xml_space(c)) {
      last = c;
    }
  }
  return {text.size(), false};
}

namespace {

// What pugixml refuses in the markup at `text[at]` == '<' that rapidxml reads, in pugixml's words
// at its places: a processing instruction without a target, "<!" opening no comment, CDATA
// section or document type, and a document type inside an element.
std::optional<XmlProblem> markup_problem(std::string_view text, std::size_t at, std::size_t depth) {
  const std::string_view rest = text.substr(at);
  const bool named = rest.size() > 2 && starts_xml_name(rest[2]);
  if (rest.starts_with("<?") && !named)
    return XmlProblem{at + 2, "Error parsing document declaration/processing instruction"};
  if (!rest.starts_with("<!") || rest.starts_with("<!--") || rest.starts_with("<![CDATA["))
    return std::nullopt;
  if (!rest.starts_with("<!DOCTYPE")) return XmlProblem{at + 2, "Could not determine tag type"};
  if (depth > 0) return XmlProblem{at, "Error parsing document type declaration"};
  // rapidxml ends a document type at its first '>' (past brackets); pugixml reads its quoted
  // literals and internal subset. Only the form both end alike is read: no '[', and no '>' inside
  // a quoted literal. MaterialX documents have no document type at all.
  char quote = 0;
  for (std::size_t i = at + 9; i < text.size() && text[i] != '>'; ++i) {
    // rapidxml counts brackets in quoted literals too.
    if (text[i] == '[' || (!quote && text[i] == '<')) {
      return XmlProblem{i,
                        "a document type holding '[' or '<' (an internal subset), which matc "
                        "does not read"};
    }
    if (quote) {
      quote = text[i] == quote ? 0 : quote;
    } else if (text[i] == '"' || text[i] == '\'') {
      quote = text[i];
    }
  }
  if (quote)
    return XmlProblem{at,
                      "a document type with a '>' in a quoted literal, which matc does not read"};
  return std::nullopt;
}

// The first problem in the document's markup structure that neither library reports alike, as an
// upper bound of the parse: an element nested deeper than kMaxXmlDepth, counting every start tag
// either library could read as one (so nothing deeper is parsed), or text (or a CDATA section)
// beside the root element, which XML 1.0 does not allow, rapidxml refuses and pugixml drops.
std::optional<XmlProblem> structure_problem(std::string_view text) {
  std::size_t depth = 0;
  // A byte-order mark before the document is not text (both libraries skip it).
  for (std::size_t at = text.starts_with("\xEF\xBB\xBF") ? 3 : 0; at < text.size();) {
    if (text[at] != '<') {
      if (depth == 0 && !is_xml_space(text[at]))
        return XmlProblem{at, std::string(kXmlTextOutsideRoot)};
      ++at;
    } else if (depth == 0 && text.substr(at).starts_with("<![CDATA[")) {
      return XmlProblem{at, std::string(kXmlTextOutsideRoot)};
    } else if (auto problem = markup_problem(text, at, depth)) {
      return problem;
    } else if (const std::size_t end = end_of_other_markup(text, at);
               end != std::string_view::npos) {
      at = end;
    } else if (text.substr(at).starts_with("</")) {
      depth -= depth > 0 ? 1 : 0;
      const std::size_t close = text.find('>', at);  // the end tag's name is not text
      at = close == std::string_view::npos ? text.size() : close + 1;
    } else {
      const auto [tag_end, empty] = end_of_start_tag(text, at);
      if (!empty && ++depth > kMaxXmlDepth)
        return XmlProblem{at, fmt::format("elements nested over {} deep", kMaxXmlDepth)};
      at = tag_end;
    }
  }
  return std::nullopt;
}

}  // namespace

std::string_view XmlElement::attribute(std::string_view attribute_name) const {
  const auto found = std::find_if(attributes.begin(), attributes.end(),
                                  [&](const XmlAttribute& a) { return a.name == attribute_name; });
  return found == attributes.end() ? std::string_view() : std::string_view(found->value);
}

bool XmlElement::has_attribute(std::string_view attribute_name) const {
  return std::any_of(attributes.begin(), attributes.end(),
                     [&](const XmlAttribute& a) { return a.name == attribute_name; });
}

const XmlElement* XmlElement::child(std::string_view tag) const {
  const auto found =
      std::find_if(children.begin(), children.end(),
                   [tag](const XmlElement* element) { return element->name == tag; });
  return found == children.end() ? nullptr : *found;
}

const XmlElement* XmlElement::child_with(std::string_view tag, std::string_view attribute_name,
                                         std::string_view value) const {
  for (const XmlElement* element : children) {
    if (!tag.empty() && element->name != tag) continue;
    for (const XmlAttribute& candidate : element->attributes)
      if (candidate.name == attribute_name && candidate.value == value) return element;
  }
  return nullptr;
}

XmlLibrary default_xml_library() {
#ifdef MATC_XML_RAPIDXML_ONLY
  return XmlLibrary::rapidxml;
#else
  return XmlLibrary::pugixml;
#endif
}

std::variant<XmlTree, XmlProblem> read_xml_tree(std::string_view text, XmlLibrary library) {
  if (auto problem = structure_problem(text)) return *problem;
#ifdef MATC_XML_RAPIDXML_ONLY
  (void)library;
  auto parsed = parse_xml_with_rapidxml(text);
#else
  auto parsed =
      library == XmlLibrary::pugixml ? parse_xml_with_pugixml(text) : parse_xml_with_rapidxml(text);
#endif
  // pugixml's refusal of a document without an element, which rapidxml reads as empty.
  if (const auto* tree = std::get_if<XmlTree>(&parsed); tree && tree->top_level.empty())
    return XmlProblem{text.size(), "No document element found"};
  return parsed;
}

}  // namespace matc
