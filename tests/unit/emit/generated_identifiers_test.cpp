// The names base/identifier_names.h refuses, derived again from the embedded templates: a material
// name is taken when a material identifier's kind followed by it is an identifier the templates
// define without a name (the shared library, the kernels), in the same shading language.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "base/embedded_templates.h"
#include "base/identifier_names.h"
#include "emit/layer_suffix.h"
#include "matc/runtime/basis.h"
#include "material/materialx_import.h"
#include "material/parse.h"
#include "pipeline/unique_names.h"

namespace {

// Every value a placeholder other than {{name}} takes in an identifier: the further layers of a
// per-material build.
std::vector<std::string> expanded(const std::string& token) {
  std::vector<std::string> out{token};
  std::vector<std::pair<std::string, std::vector<std::string>>> values{
      {"{{suffix}}", {""}}, {"{{basis}}", {}}, {"{{constant_suffix}}", {""}}};
  for (std::size_t layer = 1; layer < matc::runtime::kPerMaterialBases.size(); ++layer) {
    const matc::runtime::BasisKind basis = matc::runtime::kPerMaterialBases[layer];
    std::string upper = matc::layer_suffix(basis);
    for (char& c : upper)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    values[0].second.push_back(matc::layer_suffix(basis));
    values[1].second.push_back(std::string(matc::runtime::basis_name(basis)));
    values[2].second.push_back(upper);
  }
  for (const auto& [placeholder, options] : values) {
    std::vector<std::string> next;
    for (const std::string& text : out) {
      const std::size_t at = text.find(placeholder);
      if (at == std::string::npos) {
        next.push_back(text);
        continue;
      }
      for (const std::string& option : options) {
        std::string filled = text;
        filled.replace(at, placeholder.size(), option);
        next.push_back(filled);
      }
    }
    out = std::move(next);
  }
  return out;
}

struct Language {
  std::set<std::string> fixed;                                 // identifiers without a name
  std::set<std::pair<std::string, std::string>> per_material;  // (before, after) {{name}}
};

std::map<std::string, Language> identifiers_by_language() {
  const std::regex token(R"((?:[A-Za-z0-9_]|\{\{[a-z_]+\}\})+)");
  std::map<std::string, Language> languages;
  for (const matc::EmbeddedFile& file : matc::embedded_templates::files()) {
    const std::string path(file.path);
    Language& language = languages[path.substr(0, path.find('/'))];
    const std::string text(file.bytes);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), token);
         it != std::sregex_iterator(); ++it) {
      for (const std::string& identifier : expanded(it->str())) {
        const std::size_t name = identifier.find("{{name}}");
        if (name == std::string::npos) {
          if (identifier.find("{{") == std::string::npos &&
              (identifier.starts_with("matc_") || identifier.starts_with("MATC_")))
            language.fixed.insert(identifier);
          continue;
        }
        const std::string after = identifier.substr(name + 8);
        if (name > 0 && after.find("{{") == std::string::npos)
          language.per_material.emplace(identifier.substr(0, name), after);
      }
    }
  }
  return languages;
}

TEST(GeneratedIdentifiers, NamesTakenByLibraryAreTheTemplates) {
  std::map<std::string, std::set<std::string>> derived;  // name -> identifiers it would redefine
  for (const auto& [directory, language] : identifiers_by_language()) {
    for (const auto& [before, after] : language.per_material) {
      for (const std::string& fixed : language.fixed) {
        if (fixed.size() <= before.size() + after.size() || !fixed.starts_with(before) ||
            !fixed.ends_with(after))
          continue;
        const std::string name =
            fixed.substr(before.size(), fixed.size() - before.size() - after.size());
        // Only names the other rules admit: "EMBEDDED" in MATC_EMBEDDED_LUT_SIZE is refused
        // nowhere else but is no clash either, for the C header and the shaders never meet.
        const bool valid = std::regex_match(name, std::regex("[A-Za-z][A-Za-z0-9_]*")) &&
                           name.find("__") == std::string::npos;
        if (valid) derived[name].insert(fixed);
      }
    }
  }
  std::map<std::string, std::set<std::string>> listed;
  for (const matc::NameTakenByLibrary& taken : matc::kNamesTakenByLibrary)
    listed[std::string(taken.name)].insert(std::string(taken.identifier));
  std::set<std::string> derived_names, listed_names;
  for (const auto& [name, identifiers] : derived)
    derived_names.insert(name);
  for (const auto& [name, identifiers] : listed)
    listed_names.insert(name);
  EXPECT_EQ(derived_names, listed_names) << "update kNamesTakenByLibrary (base/identifier_names.h)";
  for (const auto& [name, identifiers] : listed) {
    if (!derived.contains(name)) continue;
    for (const std::string& identifier : identifiers)
      EXPECT_TRUE(derived[name].contains(identifier)) << name << " names " << identifier;
  }
}

TEST(GeneratedIdentifiers, InfixesAreTheTemplates) {
  std::set<std::string> derived;
  for (const auto& [directory, language] : identifiers_by_language())
    for (const auto& [before, after] : language.per_material)
      for (const auto& [longer, longer_after] : language.per_material)
        if (after == longer_after && longer.size() > before.size() && longer.starts_with(before))
          derived.insert(longer.substr(before.size()));
  const std::set<std::string> listed(matc::kIdentifierInfixes.begin(),
                                     matc::kIdentifierInfixes.end());
  EXPECT_EQ(derived, listed) << "update kIdentifierInfixes (base/identifier_names.h)";
  // The identifier identifier_neighbours names is one the templates define per material.
  for (const std::string_view infix : matc::kIdentifierInfixes) {
    bool found = false;
    for (const auto& [directory, language] : identifiers_by_language())
      found |= language.per_material.contains({"matc_fresnel_" + std::string(infix), ""});
    EXPECT_TRUE(found) << infix;
  }
}

TEST(GeneratedIdentifiers, MaterialNamesTakenByLibraryAreRefused) {
  for (const matc::NameTakenByLibrary& taken : matc::kNamesTakenByLibrary) {
    const auto problem = matc::material_name_problem(taken.name);
    ASSERT_TRUE(problem.has_value()) << taken.name;
    EXPECT_NE(problem->find(taken.identifier), std::string::npos) << *problem;
    // Importers make another name, one the rule admits.
    const std::string imported = matc::sanitized_material_name(taken.name);
    EXPECT_EQ(imported, std::string(taken.name) + "_material");
    EXPECT_FALSE(matc::material_name_problem(imported).has_value()) << imported;
  }
  // Identifiers are case-sensitive: "Sum" makes matc_fresnel_Sum.
  EXPECT_FALSE(matc::material_name_problem("Sum").has_value());
  EXPECT_FALSE(matc::material_name_problem("summary").has_value());
}

TEST(GeneratedIdentifiers, ABuildRefusesTwoNamesAnInfixApart) {
  for (const std::string_view infix : matc::kIdentifierInfixes) {
    for (const bool shorter_first : {true, false}) {
      const std::string shorter = "steel";
      const std::string longer = std::string(infix) + "steel";
      matc::UniqueNames names;
      matc::Diagnostics diagnostics;
      const matc::SourceLocation first{"a.json", 1, 10}, second{"b.json", 1, 10};
      EXPECT_TRUE(
          names.claim(shorter_first ? shorter : longer, "a.json", first, "a build", diagnostics));
      EXPECT_FALSE(
          names.claim(shorter_first ? longer : shorter, "b.json", second, "a build", diagnostics));
      ASSERT_EQ(diagnostics.items().size(), 1u);
      const std::string& message = diagnostics.items().front().message;
      EXPECT_NE(message.find("matc_fresnel_" + std::string(infix) + "steel"), std::string::npos)
          << message;
      EXPECT_NE(message.find("a.json (1:10)"), std::string::npos) << message;
    }
  }
  // Names that only share a start are not neighbours, nor are names of another case (the
  // identifiers keep it: matc_fresnel_Preintegrated_steel).
  matc::UniqueNames names;
  matc::Diagnostics diagnostics;
  EXPECT_TRUE(names.claim("steel", "a.json", {"a.json", 1, 1}, "a build", diagnostics));
  EXPECT_TRUE(
      names.claim("Preintegrated_steel", "d.json", {"d.json", 1, 1}, "a build", diagnostics));
  EXPECT_TRUE(names.claim("textured", "b.json", {"b.json", 1, 1}, "a build", diagnostics));
  EXPECT_TRUE(
      names.claim("preintegrated_steel_2", "c.json", {"c.json", 1, 1}, "a build", diagnostics));
  EXPECT_TRUE(diagnostics.items().empty());
}

// The npm package's loaders check a glTF extension's name before a snippet is filled with it.
TEST(GeneratedIdentifiers, JavaScriptListIsTheLibrarys) {
  std::ifstream file(MATC_SOURCE_DIR "/js/package/integration/build-directory.mjs");
  ASSERT_TRUE(file) << "build-directory.mjs";
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::smatch list;
  ASSERT_TRUE(std::regex_search(text, list,
                                std::regex(R"(kNamesTakenByLibrary = new Set\(\[([^\]]*)\]\))")));
  std::set<std::string> in_javascript;
  const std::string items = list[1].str();
  const std::regex quoted("\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(items.begin(), items.end(), quoted);
       it != std::sregex_iterator(); ++it)
    in_javascript.insert((*it)[1].str());
  std::set<std::string> in_library;
  for (const matc::NameTakenByLibrary& taken : matc::kNamesTakenByLibrary)
    in_library.insert(std::string(taken.name));
  EXPECT_EQ(in_javascript, in_library);
}

}  // namespace
