// libFuzzer target for the two XML readers behind MaterialX import (compiler/src/material/
// xml_tree.h): pugixml, the native library's, and rapidxml, the WebAssembly library's. On every
// document the character check lets through, what pugixml reads rapidxml reads too, and the same
// tree: element names and places, attributes in order with the same values. So a document reads
// the same in a page as in `matc`. (The other way round rapidxml is laxer in a few malformed
// constructs, docs/materialx.md; with MATC_XML_SAME_REFUSALS=1 in the environment the fuzzer
// stops at one, to find them.) Built with -DMATC_BUILD_FUZZERS=ON (clang).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string_view>
#include <variant>

#include "material/xml_tree.h"
#include "material/xml_well_formed.h"

namespace {

[[noreturn]] void differ(std::string_view what) {
  std::cerr << "pugixml and rapidxml differ: " << what << "\n";
  std::abort();
}

void require_same(const matc::XmlElement& a, const matc::XmlElement& b) {
  if (a.name != b.name) differ("an element's name");
  if (a.offset != b.offset) differ("an element's place");
  if (a.attributes.size() != b.attributes.size()) differ("an element's attribute count");
  for (std::size_t i = 0; i < a.attributes.size(); ++i) {
    if (a.attributes[i].name != b.attributes[i].name) differ("an attribute's name");
    if (a.attributes[i].value != b.attributes[i].value) differ("an attribute's value");
  }
  if (a.children.size() != b.children.size()) differ("an element's child count");
  for (std::size_t i = 0; i < a.children.size(); ++i)
    require_same(*a.children[i], *b.children[i]);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (matc::find_xml_character_problem(text)) return 0;  // refused before either reads it
  const auto pugixml = matc::read_xml_tree(text, matc::XmlLibrary::pugixml);
  // matc's own structure check refuses only what XML 1.0 forbids and pugixml lets through (text
  // beside the root), what is nested too deep, the document types the two libraries would end in
  // different places ("which matc does not read"), and what pugixml refuses itself.
  if (const auto* problem = std::get_if<matc::XmlProblem>(&pugixml);
      problem && problem->message != matc::kXmlTextOutsideRoot &&
      problem->message.find("nested over") == std::string::npos &&
      problem->message.find("which matc does not read") == std::string::npos &&
      std::holds_alternative<matc::XmlTree>(matc::parse_xml_with_pugixml(text))) {
    std::cerr << problem->offset << ": " << problem->message << "\n";
    differ("matc's structure check refuses what pugixml reads");
  }
  const auto rapidxml = matc::read_xml_tree(text, matc::XmlLibrary::rapidxml);
  const auto* a = std::get_if<matc::XmlTree>(&pugixml);
  const auto* b = std::get_if<matc::XmlTree>(&rapidxml);
  // rapidxml may read a malformed document pugixml refuses (docs/materialx.md says which); it
  // must never refuse one pugixml reads.
  if (a && !b) {
    const auto& problem = std::get<matc::XmlProblem>(rapidxml);
    std::cerr << problem.offset << ": " << problem.message << "\n";
    differ("rapidxml refuses what pugixml reads");
  }
  if (b && !a && std::getenv("MATC_XML_SAME_REFUSALS")) {
    const auto& problem = std::get<matc::XmlProblem>(pugixml);
    std::cerr << problem.offset << ": " << problem.message << "\n";
    differ("pugixml refuses what rapidxml reads");
  }
  if (!a || !b) return 0;
  if (a->top_level.size() != b->top_level.size()) differ("the number of top-level elements");
  for (std::size_t i = 0; i < a->top_level.size(); ++i)
    require_same(*a->top_level[i], *b->top_level[i]);
  return 0;
}
