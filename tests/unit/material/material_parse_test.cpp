// Material files: accepted forms, and every kind of bad input reported at its position.
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <ostream>

#include "diagnostic_text.h"
#include "material/located_json.h"
#include "material/parse.h"

namespace matc {
namespace {

// Serves files from memory so these tests never touch the file system.
FileLoader memory_loader(std::map<std::string, std::string> files) {
  return [files = std::move(files)](const std::filesystem::path& path, std::uintmax_t max_bytes) {
    const auto found = files.find(path.generic_string());
    if (found == files.end()) return LoadedFile{std::nullopt, "no such file"};
    if (found->second.size() > max_bytes) return LoadedFile{std::nullopt, "too large"};
    return LoadedFile{found->second, {}};
  };
}

ParseResult parse(const std::string& text, const FileLoader& loader = memory_loader({})) {
  return parse_material(text, "materials/m.json", loader);
}

std::string all_diagnostics(const ParseResult& result) {
  return test::diagnostic_text(result.diagnostics);
}

TEST(MaterialParse, ArtisticWithGreyScalars) {
  const auto result = parse(R"({"name": "steel", "artistic": {"reflectivity": 0.5,
                                "edge_tint": [0.1, 0.2, 0.3]}, "roughness": 0.25})");
  ASSERT_TRUE(result.material) << all_diagnostics(result);
  EXPECT_TRUE(result.diagnostics.items().empty());
  const auto& artistic = std::get<ArtisticInput>(result.material->model);
  EXPECT_EQ(artistic.reflectivity, (Rgb{0.5, 0.5, 0.5}));
  EXPECT_EQ(artistic.edge_tint, (Rgb{0.1, 0.2, 0.3}));
  EXPECT_EQ(result.material->roughness, 0.25);
  EXPECT_EQ(result.material->name_location.line, 1u);
  EXPECT_EQ(result.material->name_location.column, 10u);
}

TEST(MaterialParse, IorWithoutRoughness) {
  const auto result = parse(R"({"$schema": "../docs/material.schema.json", "name": "Gold2",
                                "description": "x", "ior": {"n": [0.2, 0.4, 1.4], "k": 3}})");
  ASSERT_TRUE(result.material) << all_diagnostics(result);
  EXPECT_FALSE(result.material->roughness.has_value());
  EXPECT_EQ(std::get<IorInput>(result.material->model).k, (Rgb{3, 3, 3}));
}

TEST(MaterialParse, SpectralPreset) {
  const auto result = parse(R"({"name": "gold", "spectral": {"preset": "Au"}})");
  ASSERT_TRUE(result.material) << all_diagnostics(result);
  const auto& spectral = std::get<SpectralInput>(result.material->model);
  EXPECT_EQ(spectral.preset, "Au");
  EXPECT_GT(spectral.spectrum.wavelength_nm.size(), 10u);
}

TEST(MaterialParse, SpectralFileIsResolvedNextToTheMaterial) {
  const auto loader = memory_loader({{"materials/data/nk.csv", "380,0.5,3\n780,0.4,4\n"}});
  const auto result = parse(R"({"name": "m", "spectral": {"file": "data/nk.csv"}})", loader);
  ASSERT_TRUE(result.material) << all_diagnostics(result);
  const auto& spectral = std::get<SpectralInput>(result.material->model);
  EXPECT_EQ(spectral.file, "data/nk.csv");
  EXPECT_EQ(spectral.resolved_file, "materials/data/nk.csv");
  EXPECT_EQ(spectral.spectrum.n.size(), 2u);
}

TEST(MaterialParse, ErrorsInsideASpectralFileNameThatFile) {
  const auto loader = memory_loader({{"materials/nk.csv", "380,0.5,3\n300,0.4,4\n"}});
  const auto result = parse(R"({"name": "m", "spectral": {"file": "nk.csv"}})", loader);
  EXPECT_FALSE(result.material);
  EXPECT_NE(all_diagnostics(result).find("materials/nk.csv:2:1: error: wavelength_nm"),
            std::string::npos)
      << all_diagnostics(result);
  // ... and, after them, where the material names that file.
  EXPECT_NE(all_diagnostics(result).find("\nmaterials/m.json:1:36: note: spectral.file: "
                                         "'materials/nk.csv' is read here\n"),
            std::string::npos)
      << all_diagnostics(result);
}

TEST(MaterialParse, F82TintAndColourSpace) {
  const auto result = parse(
      R"({"name": "m", "color_space": "lin_ap1", "f82_tint": {"f0": [0.9, 0.6, 0.3], "tint": 1}})");
  ASSERT_TRUE(result.material) << all_diagnostics(result);
  const auto& f82 = std::get<F82TintInput>(result.material->model);
  EXPECT_EQ(f82.f0, (Rgb{0.9, 0.6, 0.3}));
  EXPECT_EQ(f82.tint, (Rgb{1, 1, 1}));
  EXPECT_EQ(result.material->color_space, ColorSpace::acescg);
}

TEST(MaterialParse, ZincPresetCompilesWithAWarning) {
  const auto result = parse(R"({"name": "zinc", "spectral": {"preset": "Zn"}})");
  ASSERT_TRUE(result.material);
  ASSERT_EQ(result.diagnostics.items().size(), 1u);
  EXPECT_EQ(result.diagnostics.items()[0].severity, Severity::warning);
  EXPECT_NE(all_diagnostics(result).find("unreliable"), std::string::npos);
}

TEST(MaterialParse, UnknownFieldWarnsWithSuggestionAndStillCompiles) {
  const auto result =
      parse("{\"name\": \"m\", \"ior\": {\"n\": 1.5, \"k\": 0},\n \"roughnes\": 1}");
  ASSERT_TRUE(result.material);
  EXPECT_EQ(all_diagnostics(result),
            "materials/m.json:2:2: warning: roughnes: unknown field, ignored (did you mean "
            "'roughness'?); known fields here: $schema, name, description, artistic, ior, "
            "spectral, f82_tint, roughness, color_space, coat, film, basis\n");
}

TEST(MaterialParse, EveryErrorInAFileIsReportedInOrder) {
  const auto result = parse(
      "{\n"
      "  \"name\": \"bad name\",\n"
      "  \"artistic\": {\"reflectivity\": [1.2, 0.5, 0.5], \"edge_tint\": -1},\n"
      "  \"roughness\": \"rough\"\n"
      "}\n");
  EXPECT_FALSE(result.material);
  EXPECT_EQ(all_diagnostics(result),
            "materials/m.json:2:11: error: name: 'bad name' is not an identifier (' ' at position "
            "4); a name matching [A-Za-z][A-Za-z0-9_]*, at most 64 characters, without '__', and "
            "none of the shared library's (f82, sum, preintegrated, from_f0, ...: "
            "docs/material-format.md)\n"
            "materials/m.json:3:33: error: artistic.reflectivity[0]: 1.2 is out of range; a "
            "number in [0, 1)\n"
            "materials/m.json:3:62: error: artistic.edge_tint: -1 is out of range; a number in "
            "[0, 1]\n"
            "materials/m.json:4:16: error: roughness: is a string; a number in [0, 1]\n");
}

struct BadInput {
  std::string name;
  std::string text;
  std::string expected;  // substring of the reported diagnostics
};

// Names the case in test output instead of dumping its bytes.
void PrintTo(const BadInput& c, std::ostream* os) {
  *os << c.name;
}

class MaterialErrors : public testing::TestWithParam<BadInput> {};

TEST_P(MaterialErrors, AreLocatedAndExplained) {
  const BadInput& c = GetParam();
  const auto result = parse(c.text);
  EXPECT_FALSE(result.material);
  EXPECT_TRUE(result.diagnostics.has_errors());
  EXPECT_NE(all_diagnostics(result).find(c.expected), std::string::npos) << all_diagnostics(result);
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, MaterialErrors,
    testing::Values(
        BadInput{"EmptyFile", "", "m.json:1:1: error: syntax error while parsing value"},
        BadInput{"TrailingComma", "{\"name\": \"m\",}", "m.json:1:14: error: syntax error"},
        BadInput{"Comment", "// gold\n{}", "m.json:1:1: error: syntax error"},
        BadInput{"NotAnObject", "[1, 2]",
                 "m.json:1:1: error: the file holds an array; a JSON object"},
        BadInput{"InvalidUtf8", "{\"name\": \"g\xff\"}", "m.json:1:12: error: syntax error"},
        BadInput{"Overflow", "{\"name\": \"m\", \"ior\": {\"n\": 1e999, \"k\": 0}}",
                 "number overflow parsing '1e999'"},
        BadInput{"MissingName", "{\"ior\": {\"n\": 1.5, \"k\": 0}}",
                 "m.json:1:1: error: name: is missing; a name matching"},
        BadInput{"NameNotString", "{\"name\": 7, \"ior\": {\"n\": 1.5, \"k\": 0}}",
                 "m.json:1:10: error: name: is a number"},
        BadInput{"NameWithDash", "{\"name\": \"go-ld\", \"ior\": {\"n\": 1.5, \"k\": 0}}",
                 "name: 'go-ld' is not an identifier ('-' at position 3)"},
        BadInput{"NameStartsWithDigit", "{\"name\": \"9lives\", \"ior\": {\"n\": 1.5, \"k\": 0}}",
                 "('9' at position 1)"},
        BadInput{"NameDoubleUnderscore", "{\"name\": \"a__b\", \"ior\": {\"n\": 1.5, \"k\": 0}}",
                 "which GLSL reserves"},
        BadInput{"NameEmpty", "{\"name\": \"\", \"ior\": {\"n\": 1.5, \"k\": 0}}",
                 "name: is empty"},
        BadInput{"NameTooLong",
                 "{\"name\": \"" + std::string(65, 'a') + "\", \"ior\": {\"n\": 1.5, \"k\": 0}}",
                 "name: is 65 characters long"},
        BadInput{"NoModel", "{\"name\": \"m\"}",
                 "error: no material model is given; exactly one of artistic, ior, spectral, "
                 "f82_tint"},
        BadInput{"F82TintAboveOne",
                 "{\"name\": \"m\", \"f82_tint\": {\"f0\": 0.5, \"tint\": [1, 2, 1]}}",
                 "m.json:1:51: error: f82_tint.tint[1]: 2 is out of range; a number in [0, 1]"},
        BadInput{
            "UnknownColourSpace",
            "{\"name\": \"m\", \"color_space\": \"lin_rec790\", \"ior\": {\"n\": 1, \"k\": 3}}",
            "m.json:1:30: error: color_space: unknown colour space 'lin_rec790' (did you mean "
            "'lin_rec709'?)"},
        BadInput{"TwoModels",
                 "{\"name\": \"m\", \"ior\": {\"n\": 1.5, \"k\": 0},\n\"spectral\": {\"preset\": "
                 "\"Au\"}}",
                 "m.json:2:1: error: spectral: a second material model ('ior' is given at 1:15)"},
        BadInput{"DuplicateKey",
                 "{\"name\": \"m\",\n \"name\": \"n\", \"ior\": {\"n\": 1.5, \"k\": 0}}",
                 "m.json:2:2: error: name: is given twice (first at 1:2)"},
        BadInput{"ReflectivityOne",
                 "{\"name\": \"m\", \"artistic\": {\"reflectivity\": 1, \"edge_tint\": 0}}",
                 "artistic.reflectivity: 1 is out of range; a number in [0, 1)"},
        BadInput{"ReflectivityNegative",
                 "{\"name\": \"m\", \"artistic\": {\"reflectivity\": [0.5, -0.1, 0.5], "
                 "\"edge_tint\": 0}}",
                 "artistic.reflectivity[1]: -0.1 is out of range"},
        BadInput{"EdgeTintAboveOne",
                 "{\"name\": \"m\", \"artistic\": {\"reflectivity\": 0.5, \"edge_tint\": 1.5}}",
                 "artistic.edge_tint: 1.5 is out of range; a number in [0, 1]"},
        BadInput{"MissingEdgeTint", "{\"name\": \"m\", \"artistic\": {\"reflectivity\": 0.5}}",
                 "m.json:1:27: error: artistic.edge_tint: is missing"},
        BadInput{"ArtisticNotObject", "{\"name\": \"m\", \"artistic\": [0.5]}",
                 "artistic: is an array; an object with the fields reflectivity, edge_tint"},
        BadInput{"WrongLength", "{\"name\": \"m\", \"ior\": {\"n\": [1, 2], \"k\": 0}}",
                 "ior.n: has 2 elements"},
        BadInput{"StringComponent", "{\"name\": \"m\", \"ior\": {\"n\": [1, \"2\", 3], \"k\": 0}}",
                 "ior.n[1]: is a string"},
        BadInput{"NegativeN", "{\"name\": \"m\", \"ior\": {\"n\": -1, \"k\": 0}}",
                 "ior.n: -1 is out of range; a number in [0, 1000]"},
        BadInput{"HugeK", "{\"name\": \"m\", \"ior\": {\"n\": 1, \"k\": 1e6}}",
                 "ior.k: 1000000 is out of range"},
        BadInput{"VacuumChannel", "{\"name\": \"m\", \"ior\": {\"n\": [1, 0, 1], \"k\": 0}}",
                 "ior.n[1]: n = k = 0 in the G channel is not a material"},
        BadInput{"UnknownPreset", "{\"name\": \"m\", \"spectral\": {\"preset\": \"Gold\"}}",
                 "spectral.preset: unknown preset 'Gold'; one of Ag, Al, Au"},
        BadInput{"PresetTypo", "{\"name\": \"m\", \"spectral\": {\"preset\": \"au\"}}",
                 "(did you mean 'Au'?)"},
        BadInput{"PresetAndFile",
                 "{\"name\": \"m\", \"spectral\": {\"preset\": \"Au\", \"file\": \"x.csv\"}}",
                 "spectral: gives both preset and file"},
        BadInput{"MissingSpectralFile", "{\"name\": \"m\", \"spectral\": {\"file\": \"nk.csv\"}}",
                 "spectral.file: cannot read 'materials/nk.csv': no such file"},
        BadInput{"RoughnessAboveOne",
                 "{\"name\": \"m\", \"ior\": {\"n\": 1.5, \"k\": 0}, \"roughness\": 1.01}",
                 "roughness: 1.01 is out of range; a number in [0, 1]"},
        BadInput{"DeepNesting",
                 "{\"name\": \"m\", \"x\": " + std::string(100, '[') + std::string(100, ']') + "}",
                 "nesting deeper than 64 levels"}),
    [](const testing::TestParamInfo<BadInput>& param) { return param.param.name; });

TEST(LocatedJson, RecordsValueAndKeyOffsets) {
  const std::string text = "{\n  \"a\": [10, {\"b\": true}],\n  \"c\": \"x\"\n}";
  const auto parsed = parse_located_json(text);
  const auto& json = std::get<LocatedJson>(parsed);
  EXPECT_EQ(json.value_offset(""), 0u);
  EXPECT_EQ(text.substr(json.value_offset("/a"), 3), "[10");
  EXPECT_EQ(text.substr(json.value_offset("/a/0"), 2), "10");
  EXPECT_EQ(text.substr(json.value_offset("/a/1/b"), 4), "true");
  EXPECT_EQ(text.substr(json.key_or_value_offset("/c"), 3), "\"c\"");
  EXPECT_EQ(text.substr(json.value_offset("/c"), 3), "\"x\"");
}

TEST(LocatedJson, FieldPathsReadLikeCode) {
  EXPECT_EQ(field_path("/artistic/reflectivity/1"), "artistic.reflectivity[1]");
  EXPECT_EQ(field_path("/a~1b/c~0d"), "a/b.c~d");
  EXPECT_EQ(field_path(""), "");
}

TEST(MaterialNames, FollowTheDocumentedRule) {
  EXPECT_FALSE(material_name_problem("gold"));
  EXPECT_FALSE(material_name_problem("Gold_2"));
  EXPECT_FALSE(material_name_problem("a_b_c"));
  EXPECT_TRUE(material_name_problem("_gold"));
  EXPECT_TRUE(material_name_problem("gold__x"));
  EXPECT_TRUE(material_name_problem("g\xc3\xb6ld"));
  EXPECT_TRUE(material_name_problem("../etc"));
}

TEST(MaterialParse, FilmTakesOpenPbrDefaultsButWeightOneAndNeedsAThickness) {
  const auto result =
      parse("{\"name\": \"m\", \"spectral\": {\"preset\": \"Ti\"}, \"film\": {\"thickness\": 40}}");
  ASSERT_TRUE(result.material);
  ASSERT_TRUE(result.material->film);
  EXPECT_EQ(result.material->film->weight, 1.0);
  EXPECT_EQ(result.material->film->ior, 1.4);
  EXPECT_EQ(result.material->film->thickness_nm, 40.0);
  EXPECT_TRUE(result.diagnostics.items().empty());
  const auto given = parse(
      "{\"name\": \"m\", \"ior\": {\"n\": 0.2, \"k\": 3.5}, \"film\": {\"weight\": 0.5, "
      "\"ior\": 2.3, \"thickness\": 300}}");
  ASSERT_TRUE(given.material);
  EXPECT_EQ(given.material->film->weight, 0.5);
  EXPECT_EQ(given.material->film->ior, 2.3);
  EXPECT_EQ(given.material->film->thickness_nm, 300.0);
  const auto missing =
      parse("{\"name\": \"m\", \"ior\": {\"n\": 0.2, \"k\": 3.5}, \"film\": {\"ior\": 2.3}}");
  EXPECT_FALSE(missing.material);
  EXPECT_NE(all_diagnostics(missing).find("film.thickness: is missing"), std::string::npos);
}

TEST(MaterialParse, CoatTakesOpenPbrDefaultsButWeightOne) {
  const auto result = parse("{\"name\": \"m\", \"ior\": {\"n\": 0.2, \"k\": 3.5}, \"coat\": {}}");
  ASSERT_TRUE(result.material);
  ASSERT_TRUE(result.material->coat);
  const CoatInput& coat = *result.material->coat;
  EXPECT_EQ(coat.weight, 1.0);
  EXPECT_EQ(coat.ior, 1.6);
  EXPECT_EQ(coat.roughness, 0.0);
  EXPECT_EQ(coat.color, (Rgb{1.0, 1.0, 1.0}));
  EXPECT_TRUE(result.diagnostics.items().empty());
}

TEST(MaterialParse, CoatReadsEveryFieldWithEveryModel) {
  for (const char* model :
       {"\"ior\": {\"n\": 0.2, \"k\": 3.5}",
        "\"artistic\": {\"reflectivity\": 0.9, \"edge_tint\": 0.5}",
        "\"f82_tint\": {\"f0\": 0.9, \"tint\": 0.8}", "\"spectral\": {\"preset\": \"Cu\"}"}) {
    const auto result = parse(std::string("{\"name\": \"m\", ") + model +
                              ", \"coat\": {\"weight\": 0.5, \"ior\": 1.45, \"roughness\": 0.2, "
                              "\"color\": [0.9, 0.8, 0.7]}}");
    ASSERT_TRUE(result.material) << model;
    const CoatInput& coat = *result.material->coat;
    EXPECT_EQ(coat.weight, 0.5);
    EXPECT_EQ(coat.ior, 1.45);
    EXPECT_EQ(coat.roughness, 0.2);
    EXPECT_EQ(coat.color, (Rgb{0.9, 0.8, 0.7}));
  }
}

TEST(MaterialParse, NoCoatBlockMeansNoCoat) {
  const auto result = parse("{\"name\": \"m\", \"ior\": {\"n\": 0.2, \"k\": 3.5}}");
  ASSERT_TRUE(result.material);
  EXPECT_FALSE(result.material->coat);
}

}  // namespace
}  // namespace matc
