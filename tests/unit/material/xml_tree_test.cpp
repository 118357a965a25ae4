// MaterialX's two XML readers (compiler/src/material/xml_tree.h): pugixml, the native library's,
// and rapidxml, the WebAssembly library's, read every example document and the catalogue's to the
// same tree, expand attribute values as pugixml does, and refuse the same documents with the same
// words at the same places where the difference would show (matc_xml_tree_fuzzer goes further).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>

#include "material/xml_tree.h"
#include "material/xml_well_formed.h"

namespace matc {
namespace {

constexpr XmlLibrary kLibraries[] = {XmlLibrary::pugixml, XmlLibrary::rapidxml};

std::string library_name(XmlLibrary library) {
  return library == XmlLibrary::pugixml ? "pugixml" : "rapidxml";
}

void expect_same(const XmlElement& a, const XmlElement& b, const std::string& where) {
  ASSERT_EQ(a.name, b.name) << where;
  EXPECT_EQ(a.offset, b.offset) << where << " <" << a.name << ">";
  ASSERT_EQ(a.attributes.size(), b.attributes.size()) << where << " <" << a.name << ">";
  for (std::size_t i = 0; i < a.attributes.size(); ++i) {
    EXPECT_EQ(a.attributes[i].name, b.attributes[i].name) << where;
    EXPECT_EQ(a.attributes[i].value, b.attributes[i].value) << where << " " << a.attributes[i].name;
  }
  ASSERT_EQ(a.children.size(), b.children.size()) << where << " <" << a.name << ">";
  for (std::size_t i = 0; i < a.children.size(); ++i) {
    EXPECT_EQ(a.children[i]->parent, &a);
    expect_same(*a.children[i], *b.children[i], where);
  }
}

XmlTree read_both_alike(const std::string& text, const std::string& where = "document") {
  auto a = read_xml_tree(text, XmlLibrary::pugixml);
  auto b = read_xml_tree(text, XmlLibrary::rapidxml);
  EXPECT_TRUE(std::holds_alternative<XmlTree>(a)) << where << ": pugixml refuses";
  EXPECT_TRUE(std::holds_alternative<XmlTree>(b)) << where << ": rapidxml refuses";
  if (!std::holds_alternative<XmlTree>(a) || !std::holds_alternative<XmlTree>(b)) return {};
  const XmlTree& x = std::get<XmlTree>(a);
  const XmlTree& y = std::get<XmlTree>(b);
  EXPECT_EQ(x.top_level.size(), y.top_level.size()) << where;
  for (std::size_t i = 0; i < std::min(x.top_level.size(), y.top_level.size()); ++i)
    expect_same(*x.top_level[i], *y.top_level[i], where);
  return std::move(std::get<XmlTree>(b));
}

// Both refuse `text` with `message` at byte `offset`.
void expect_refused_alike(const std::string& text, std::size_t offset, const std::string& message) {
  for (const XmlLibrary library : kLibraries) {
    const auto read = read_xml_tree(text, library);
    ASSERT_TRUE(std::holds_alternative<XmlProblem>(read)) << library_name(library) << ": " << text;
    const XmlProblem& problem = std::get<XmlProblem>(read);
    EXPECT_EQ(problem.message, message) << library_name(library) << ": " << text;
    EXPECT_EQ(problem.offset, offset) << library_name(library) << ": " << text;
  }
}

TEST(XmlTree, EveryMaterialXDocumentOfTheRepositoryReadsAlike) {
  int documents = 0;
  for (const char* folder : {MATC_SOURCE_DIR "/examples", MATC_SOURCE_DIR "/tests/data/bad_inputs",
                             MATC_SOURCE_DIR "/tests/fuzz/corpus_materialx"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
      const std::string path = entry.path().string();
      if (!entry.is_regular_file() || std::filesystem::file_size(entry.path()) > (1u << 20))
        continue;
      if (entry.path().extension() != ".mtlx" &&
          folder != std::string(MATC_SOURCE_DIR "/tests/fuzz/corpus_materialx"))
        continue;
      std::ifstream file(entry.path(), std::ios::binary);
      std::stringstream bytes;
      bytes << file.rdbuf();
      const std::string text = bytes.str();
      if (find_xml_character_problem(text)) continue;  // refused before either reads it
      const auto a = read_xml_tree(text, XmlLibrary::pugixml);
      const auto b = read_xml_tree(text, XmlLibrary::rapidxml);
      ASSERT_EQ(a.index(), b.index()) << path;
      if (const auto* problem = std::get_if<XmlProblem>(&a)) {
        EXPECT_EQ(problem->offset, std::get<XmlProblem>(b).offset) << path;
        EXPECT_EQ(problem->message, std::get<XmlProblem>(b).message) << path;
      } else {
        read_both_alike(text, path);
      }
      ++documents;
    }
  }
  EXPECT_GT(documents, 40);
}

TEST(XmlTree, AttributeValuesAreExpandedAsPugixmlExpandsThem) {
  const std::string text =
      "<?xml version=\"1.0\"?>\n<!-- c --><!DOCTYPE m>\n"
      "<m a=\"0.9,\r\n0.6\t0.3\" b='&lt;&gt;&amp;&apos;&quot;' c=\"&#65;&#x42;&#x20AC;&#128512;\""
      " d=\"&amx;&a&q;&#;&#x;&#12x;&unknown;\" e='&#10;&#9;' f=\"<![CDATA[ x ]]>\">"
      "<n x = \"1\" /><![CDATA[<n/>]]><?pi <n/> ?><n/></m>";
  const XmlTree tree = read_both_alike(text);
  ASSERT_EQ(tree.top_level.size(), 1u);
  const XmlElement& m = *tree.top_level.front();
  EXPECT_EQ(m.offset, text.find("<m"));
  EXPECT_EQ(m.attribute("a"), "0.9, 0.6 0.3");  // tab, line feed, CR LF: one space each
  EXPECT_EQ(m.attribute("b"), "<>&'\"");
  EXPECT_EQ(m.attribute("c"), "AB\u20AC\U0001F600");
  EXPECT_EQ(m.attribute("d"), "&amx;&a&q;&#;&#x;&#12x;&unknown;");  // kept as written
  EXPECT_EQ(m.attribute("e"), "\n\t");  // references are not white-space normalised
  EXPECT_EQ(m.attribute("f"), "<![CDATA[ x ]]>");
  ASSERT_EQ(m.children.size(), 2u);  // the CDATA section and the instruction hold no element
  EXPECT_EQ(m.children[0]->offset, text.find("<n x"));
  EXPECT_EQ(m.children[0]->attribute("x"), "1");
  EXPECT_EQ(m.child("n"), m.children[0]);
  EXPECT_EQ(m.child_with("n", "x", "1"), m.children[0]);
  EXPECT_EQ(m.child_with("", "x", "2"), nullptr);
  EXPECT_FALSE(m.has_attribute("g"));
  EXPECT_EQ(m.attribute("g"), "");
}

TEST(XmlTree, AByteOrderMarkAndTopLevelMarkupAreNotText) {
  const XmlTree tree =
      read_both_alike("\xEF\xBB\xBF<?xml version=\"1.0\"?>\r\n<a/>\n<!-- after -->\n<?pi?>\n");
  ASSERT_EQ(tree.top_level.size(), 1u);
  EXPECT_EQ(tree.top_level.front()->offset, 26u);
}

TEST(XmlTree, BothRefuseWithTheSameWordsAtTheSamePlace) {
  expect_refused_alike("<a>\n  <b>\n  </c>\n</a>", 14, "Start-end tags mismatch");
  expect_refused_alike("", 0, "No document element found");
  expect_refused_alike("<!-- only a comment -->  ", 25, "No document element found");
  expect_refused_alike("<a/>\ntrailing", 5, std::string(kXmlTextOutsideRoot));
  expect_refused_alike("leading<a/>", 0, std::string(kXmlTextOutsideRoot));
  expect_refused_alike("<a/><![CDATA[x]]>", 4, std::string(kXmlTextOutsideRoot));
  expect_refused_alike("<? x?><a/>", 2,
                       "Error parsing document declaration/processing instruction");
  expect_refused_alike("<a><!x></a>", 5, "Could not determine tag type");
  expect_refused_alike("<a><!DOCTYPE a></a>", 3, "Error parsing document type declaration");
  // Document types both libraries end at the same '>' read alike; the others are refused.
  read_both_alike("<!DOCTYPE materialx SYSTEM \"materialx.dtd\">\n<materialx/>");
  const std::string subset =
      "a document type holding '[' or '<' (an internal subset), which matc does not read";
  expect_refused_alike("<!DOCTYPE a [<!ELEMENT a ANY>]><a/>", 12, subset);
  expect_refused_alike("<!DOCTYPE a SYSTEM \"a[.dtd\"><a/>", 21, subset);
  expect_refused_alike("<!DOCTYPE a SYSTEM \"x>y\"><a/>", 0,
                       "a document type with a '>' in a quoted literal, which matc does not read");
  std::string deep;
  for (std::size_t i = 0; i <= kMaxXmlDepth; ++i)
    deep += "<e>";
  expect_refused_alike(deep, 3 * kMaxXmlDepth, "elements nested over 256 deep");
  // Nesting that deep with every element closed reads.
  std::string shallow;
  for (std::size_t i = 0; i < kMaxXmlDepth; ++i)
    shallow += "<e a='>'>";
  for (std::size_t i = 0; i < kMaxXmlDepth; ++i)
    shallow += "</e>";
  read_both_alike(shallow);
}

// Start tags pugixml refuses and rapidxml would read: refused by both.
TEST(XmlTree, NamesOutsidePugixmlsCharactersAreRefusedByBoth) {
  for (const char* text : {"<input=\"x\"/>", "<a b$c='1'/>", "<1a/>", "<a 1b='1'/>",
                           "<a b='1'c='2'/>", "<a$/>", "<a b=\"1\"\"/>"}) {
    for (const XmlLibrary library : kLibraries) {
      EXPECT_TRUE(std::holds_alternative<XmlProblem>(read_xml_tree(text, library)))
          << library_name(library) << " reads " << text;
    }
  }
}

}  // namespace
}  // namespace matc
