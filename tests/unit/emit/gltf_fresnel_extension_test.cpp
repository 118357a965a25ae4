// glTF out: the asset written back with MATC_materials_fresnel in each metal, every other byte as
// it was (the JSON edited in place, a GLB's later chunks carried), a second run replacing the
// first's extension, a stale one removed, and the entries a reader could take two ways refused.
#include <gtest/gtest.h>

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "diagnostic_text.h"
#include "emit/gltf_fresnel_extension.h"
#include "formats/glb_container.h"
#include "glb_bytes.h"
#include "matc/matc.h"
#include "matc/runtime/baked_coefficients.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/f0_table.h"
#include "matc/runtime/shipped_bases.h"

namespace matc {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

const ordered_json kExtension = {{"name", "a"}, {"coefficients", {{1, 0, 0, 0}}}};
const std::string kMember = R"("MATC_materials_fresnel":{"name":"a","coefficients":[[1,0,0,0]]})";

// The asset `text` (.gltf) with `extensions`; fails the test on an error.
std::string written(const std::string& text,
                    const std::map<std::size_t, ordered_json>& extensions) {
  Diagnostics diagnostics;
  const auto result = gltf_with_fresnel_extensions(text, false, extensions, "a.gltf", diagnostics);
  EXPECT_TRUE(result) << test::diagnostic_text(diagnostics);
  return result ? result->bytes : std::string();
}

std::string refusal(const std::string& text,
                    const std::map<std::size_t, ordered_json>& extensions) {
  Diagnostics diagnostics;
  const auto result = gltf_with_fresnel_extensions(text, false, extensions, "a.gltf", diagnostics);
  EXPECT_FALSE(result);
  return test::diagnostic_text(diagnostics);
}

TEST(GltfFresnelExtension, InsertsTheExtensionAndKeepsEveryOtherByte) {
  // Formatting, number spellings, key order and unknown members as the asset has them.
  const std::string text =
      "{\n  \"asset\" : {\"version\": \"2.0\", \"generator\": \"x\"},\n"
      "  \"materials\": [\n    {\"name\": \"m\", \"pbrMetallicRoughness\": {\"metallicFactor\": "
      "1.0e0}},"
      "\n    {\"extensions\": {}},\n    {\"extensions\": {\"KHR_x\": {\"v\": 0.10}}}\n  ],"
      "\n  \"extras\": {\"\\u00e9\": [1e2]}\n}\n";
  const std::string out = written(text, {{0, kExtension}, {1, kExtension}, {2, kExtension}});
  const std::string expected =
      "{\"extensionsUsed\":[\"MATC_materials_fresnel\"],\n  \"asset\" : {\"version\": \"2.0\", "
      "\"generator\": \"x\"},\n  \"materials\": [\n    {\"extensions\":{" +
      kMember +
      "},\"name\": \"m\", \"pbrMetallicRoughness\": {\"metallicFactor\": 1.0e0}},\n    "
      "{\"extensions\": {" +
      kMember + "}},\n    {\"extensions\": {" + kMember +
      ",\"KHR_x\": {\"v\": 0.10}}}\n  ],\n  \"extras\": {\"\\u00e9\": [1e2]}\n}\n";
  EXPECT_EQ(out, expected);
}

TEST(GltfFresnelExtension, ListsItInExtensionsUsedOnce) {
  EXPECT_EQ(written(R"({"extensionsUsed": [], "materials": [{}]})", {{0, kExtension}}),
            R"({"extensionsUsed": ["MATC_materials_fresnel"], "materials": [{"extensions":{)" +
                kMember + "}}]}");
  EXPECT_EQ(
      written(R"({"extensionsUsed": ["KHR_a"], "materials": [{}]})", {{0, kExtension}}),
      R"({"extensionsUsed": ["MATC_materials_fresnel","KHR_a"], "materials": [{"extensions":{)" +
          kMember + "}}]}");
  const std::string listed = R"({"extensionsUsed": ["MATC_materials_fresnel"], "materials": [{}]})";
  EXPECT_EQ(written(listed, {{0, kExtension}}),
            R"({"extensionsUsed": ["MATC_materials_fresnel"], "materials": [{"extensions":{)" +
                kMember + "}}]}");
}

TEST(GltfFresnelExtension, ASecondRunReplacesTheFirstsAndGivesTheSameBytes) {
  const std::string text = R"({"materials": [{"name": "m"}, {"name": "n"}]})";
  const std::string once = written(text, {{0, kExtension}, {1, kExtension}});
  EXPECT_EQ(written(once, {{0, kExtension}, {1, kExtension}}), once);
  ordered_json changed = kExtension;
  changed["name"] = "b";
  const std::string twice = written(once, {{0, changed}, {1, kExtension}});
  EXPECT_NE(twice.find(R"({"name":"b")"), std::string::npos) << twice;
  EXPECT_EQ(twice.find(R"("name":"a","coefficients":[[1,0,0,0]]},"name": "m")"), std::string::npos)
      << twice;
}

TEST(GltfFresnelExtension, AMaterialNoLongerAMetalLosesTheExtension) {
  const std::string first =
      R"({"materials": [{"extensions": {"MATC_materials_fresnel": {"x": 1}, "K": {}}}]})";
  EXPECT_EQ(written(first, {}), R"({"materials": [{"extensions": { "K": {}}}]})");
  const std::string last =
      R"({"materials": [{"extensions": {"K": {} , "MATC_materials_fresnel": {"x": [1]} }}]})";
  EXPECT_EQ(written(last, {}), R"({"materials": [{"extensions": {"K": {}  }}]})");
  const std::string only = R"({"materials": [{"extensions": {"MATC_materials_fresnel": {}}}]})";
  EXPECT_EQ(written(only, {}), R"({"materials": [{"extensions": {}}]})");
}

TEST(GltfFresnelExtension, RefusesWhatAReaderCouldTakeTwoWays) {
  EXPECT_NE(refusal(R"({"materials": [{"name": "a", "name": "b"}]})", {{0, kExtension}})
                .find("materials[0].name: given twice"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"materials": [{"extensions": []}]})", {{0, kExtension}})
                .find("materials[0].extensions: is not an object"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"materials": [{"extensions": {"MATC_materials_fresnel": 1}}]})",
                    {{0, kExtension}})
                .find("materials[0].extensions.MATC_materials_fresnel: is not an object"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"extensionsUsed": {}, "materials": [{}]})", {{0, kExtension}})
                .find("extensionsUsed: is not an array"),
            std::string::npos);
}

TEST(GltfFresnelExtension, AGlbKeepsItsBinAndLaterChunksByteForByte) {
  const std::string bin("\x01\x00\x02\x03", 4);
  const std::string other_chunk = std::string("\x04\x00\x00\x00XTRA", 8) + "abcd";
  const std::string asset = test::glb_bytes(R"({"materials": [{}]})", bin, other_chunk);
  Diagnostics diagnostics;
  const auto result =
      gltf_with_fresnel_extensions(asset, true, {{0, kExtension}}, "a.glb", diagnostics);
  ASSERT_TRUE(result) << test::diagnostic_text(diagnostics);
  EXPECT_EQ(glb_layout_problem(result->bytes), "");
  const GlbParts parts = glb_parts(result->bytes);
  EXPECT_EQ(parts.json,
            R"({"extensionsUsed":["MATC_materials_fresnel"],"materials": [{"extensions":{)" +
                kMember + "}}]}");
  EXPECT_EQ(std::string(parts.after_json), glb_parts(asset).after_json);
  EXPECT_EQ(result->bytes.size() % 4, 0u);
  // What an independent writer makes of the same JSON and chunks.
  EXPECT_EQ(result->bytes, test::glb_bytes(std::string(parts.json), bin, other_chunk));
}

TEST(GltfFresnelExtension, NamesTheFilesAGltfNeedsBesideIt) {
  Diagnostics diagnostics;
  const auto result = gltf_with_fresnel_extensions(
      R"({"materials": [{}], "buffers": [{"uri": "a.bin"}, {"uri": "data:x;base64,"}, {}],
          "images": [{"uri": "t%20x.png"}]})",
      false, {{0, kExtension}}, "a.gltf", diagnostics);
  ASSERT_TRUE(result) << test::diagnostic_text(diagnostics);
  EXPECT_EQ(result->external_uris, (std::vector<std::string>{"a.bin", "t%20x.png"}));
}

// The public call: the metals compiled as compile() compiles them, the extension carrying them.
TEST(GltfFresnelExtension, ThePublicCallCompilesEachMetalIntoItsMaterial) {
  const std::string text = R"({"asset": {"version": "2.0"}, "materials": [
      {"name": "plastic", "pbrMetallicRoughness": {"metallicFactor": 0}},
      {"name": "Gold", "pbrMetallicRoughness": {"baseColorFactor": [1, 0.78, 0.34, 1]},
       "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1}}}]})";
  const api::GltfAsset asset = api::compile_gltf(text, "car.gltf", {"f82", "", ""});
  ASSERT_EQ(asset.materials.size(), 1u);
  const api::CompiledMaterial direct =
      api::compile(api::parse_materials(text, "car.gltf").front(), {"f82", "", ""});
  const json written_json = json::parse(asset.bytes);
  EXPECT_FALSE(written_json["materials"][0].contains("extensions"));
  const json& extension = written_json["materials"][1]["extensions"]["MATC_materials_fresnel"];
  EXPECT_EQ(extension["name"], "Gold");
  EXPECT_EQ(extension["basis"], "f82");
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_EQ(extension["coefficients"][c][i].get<double>(), direct.coefficients()[c][i]);
  ASSERT_TRUE(direct.coat());
  EXPECT_EQ(extension["coat"]["ior"], 1.5);
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_EQ(extension["coat"]["underCoatCoefficients"][c][i].get<double>(),
                direct.coat()->under_coat_coefficients[c][i]);
  EXPECT_THROW(api::compile_gltf(text, "car.json"), std::invalid_argument);
  EXPECT_THROW(api::compile_gltf(text, "car.gltf", {"nope", "", ""}), std::invalid_argument);
  EXPECT_THROW(api::compile_gltf(R"({"materials": []})", "car.gltf"), api::MaterialError);
}

// A textured metal of Schlick's curve carries its coefficients at F0 = 0, with which a loader
// follows the texture: the coefficients are linear in F0, so F0 (1, 0, 0, 0) + (1 - F0) times
// them is the compile at the factor. Under an edge colour or a coat the curve is not linear in F0,
// and an untextured metal needs nothing more: neither gets them.
// Rows R, G, B of c_0..c_3 as the extension writes them.
runtime::Coefficients coefficient_rows(const json& value) {
  runtime::Coefficients out{};
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < 4; ++i)
      out[c][i] = value[c][i].get<double>();
  return out;
}

TEST(GltfFresnelExtension, ATexturedSchlickMetalCarriesItsCoefficientsAtZeroF0) {
  const std::string texture = R"("baseColorTexture": {"index": 0})";
  const std::string edge =
      R"("extensions": {"KHR_materials_specular": {"specularColorFactor": [0.7, 0.8, 0.9],
         "extensions": {"EXT_materials_specular_edge_color": {"specularEdgeColorEnabled": true}}}})";
  const std::string text = R"({"asset": {"version": "2.0"}, "materials": [
      {"name": "Trim", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.6, 1], )" +
                           texture + R"(}},
      {"name": "Plain", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.6, 1]}},
      {"name": "Edge", "pbrMetallicRoughness": {)" +
                           texture + "}, " + edge + R"(},
      {"name": "Paint", "pbrMetallicRoughness": {)" +
                           texture + R"(},
       "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1}}}],
      "textures": [{"source": 0}], "images": [{"uri": "t.png"}]})";
  for (const char* basis : {"powers", "paper", "f82"}) {
    const api::GltfAsset asset = api::compile_gltf(text, "car.gltf", {basis, "acescg", ""});
    const json written_json = json::parse(asset.bytes);
    const auto extension = [&](std::size_t i) -> const json& {
      return written_json["materials"][i]["extensions"]["MATC_materials_fresnel"];
    };
    for (std::size_t i = 1; i < 4; ++i)
      EXPECT_FALSE(extension(i).contains("zeroF0Coefficients")) << basis << " " << i;
    const json& trim = extension(0);
    ASSERT_TRUE(trim.contains("zeroF0Coefficients")) << basis;
    const api::CompiledMaterial zero = api::compile(
        api::parse_materials(R"({"name": "z", "f82_tint": {"f0": [0, 0, 0], "tint": [1, 1, 1]}})",
                             "z.json")
            .front(),
        {basis, "acescg", ""});
    // The runtime's per-pixel coefficients (the shaders' matc_coefficients_from_f0) at the
    // factor are the compile at the factor.
    const runtime::Coefficients zero_rows = coefficient_rows(trim["zeroF0Coefficients"]);
    const runtime::Coefficients factor_rows = coefficient_rows(trim["coefficients"]);
    const runtime::Coefficients per_pixel = runtime::coefficients_from_f0(
        zero_rows, {factor_rows[0][0], factor_rows[1][0], factor_rows[2][0]});
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t i = 0; i < 4; ++i)
        EXPECT_NEAR(per_pixel[c][i], factor_rows[c][i], 1e-12) << basis;
    for (std::size_t c = 0; c < 3; ++c) {
      const double f0 = trim["coefficients"][c][0].get<double>();
      for (std::size_t i = 0; i < 4; ++i) {
        const double at_zero = trim["zeroF0Coefficients"][c][i].get<double>();
        EXPECT_NEAR(at_zero, zero.coefficients()[c][i], 1e-12) << basis;
        EXPECT_NEAR(f0 * (i == 0 ? 1.0 : 0.0) + (1 - f0) * at_zero,
                    trim["coefficients"][c][i].get<double>(), 1e-12)
            << basis << " channel " << c << " c_" << i;
      }
    }
  }
}

// A textured metal under an edge colour or a coat carries its F0 table (in its own colour space):
// 33 entries, the coated one's under the coat too, and at the factor the table gives the
// compile's F within the table's error (docs/gltf.md). A Schlick metal and an untextured one do
// not; nor does a compile in another working space, which mixes the channels.
TEST(GltfFresnelExtension, ATexturedMetalUnderAnEdgeColourOrACoatCarriesItsF0Table) {
  const std::string texture = R"("baseColorTexture": {"index": 0})";
  const std::string text = R"({"asset": {"version": "2.0"}, "materials": [
      {"name": "Trim", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.6, 1], )" +
                           texture + R"(}},
      {"name": "Edge", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.6, 1], )" +
                           texture + R"(},
       "extensions": {"KHR_materials_specular": {"specularColorFactor": [0.7, 0.8, 0.9],
         "extensions": {"EXT_materials_specular_edge_color": {"specularEdgeColorEnabled": true}}}}},
      {"name": "Paint", "pbrMetallicRoughness": {"baseColorFactor": [0.55, 0.06, 0.05, 1], )" +
                           texture + R"(},
       "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1}}},
      {"name": "Plain", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.6, 1]},
       "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1}}}],
      "textures": [{"source": 0}], "images": [{"uri": "t.png"}]})";
  const api::GltfAsset asset = api::compile_gltf(text, "car.gltf");
  const json written = json::parse(asset.bytes);
  const auto extension = [&](std::size_t i) -> const json& {
    return written["materials"][i]["extensions"]["MATC_materials_fresnel"];
  };
  EXPECT_FALSE(extension(0).contains("f0Table"));
  EXPECT_FALSE(extension(3).contains("f0Table"));
  const runtime::ShaderBasis& shader = runtime::shipped_shader_basis(runtime::kDefaultBasis);
  for (const std::size_t i : {std::size_t{1}, std::size_t{2}}) {
    ASSERT_TRUE(extension(i).contains("f0Table")) << i;
    const json& entries = extension(i)["f0Table"];
    ASSERT_EQ(entries["coefficients"].size(), runtime::kF0TableEntries);
    const bool coated = i == 2;
    EXPECT_EQ(entries.contains("underCoatCoefficients"), coated);
    runtime::F0Table table;
    for (std::size_t e = 0; e < runtime::kF0TableEntries; ++e)
      table.in_air[e] = coefficient_rows(entries["coefficients"][e]);
    if (coated) {
      table.under_coat.emplace();
      for (std::size_t e = 0; e < runtime::kF0TableEntries; ++e)
        (*table.under_coat)[e] = coefficient_rows(entries["underCoatCoefficients"][e]);
    }
    const runtime::Coefficients compiled = coefficient_rows(extension(i)["coefficients"]);
    const Rgb factor{compiled[0][0], compiled[1][0], compiled[2][0]};
    const runtime::Coefficients in_air = runtime::coefficients_from_f0_table(table, factor);
    runtime::CoatCoefficients coat, compiled_coat;
    if (coated) {
      const json& c = extension(i)["coat"];
      compiled_coat.under_coat = coefficient_rows(c["underCoatCoefficients"]);
      for (std::size_t k = 0; k < 4; ++k)
        compiled_coat.coat[k] = c["coatCoefficients"][k].get<double>();
      compiled_coat.weight = c["weight"].get<double>();
      compiled_coat.ior = c["ior"].get<double>();
      coat = compiled_coat;
      coat.under_coat = runtime::under_coat_coefficients_from_f0_table(table, factor);
    }
    for (int j = 0; j <= 64; ++j) {
      const double mu = j / 64.0;
      const Rgb ours = coated ? runtime::evaluate_coated_fresnel(in_air, coat, shader, mu).total()
                              : runtime::evaluate_fresnel(in_air, shader, mu);
      const Rgb expected =
          coated ? runtime::evaluate_coated_fresnel(compiled, compiled_coat, shader, mu).total()
                 : runtime::evaluate_fresnel(compiled, shader, mu);
      for (std::size_t c = 0; c < 3; ++c)
        EXPECT_NEAR(ours[c], expected[c], 0.006) << i << " mu " << mu << " channel " << c;
    }
  }
  const api::GltfAsset elsewhere = api::compile_gltf(text, "car.gltf", {"", "acescg", ""});
  const json mixed = json::parse(elsewhere.bytes);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_FALSE(mixed["materials"][i]["extensions"]["MATC_materials_fresnel"].contains("f0Table"));
}

}  // namespace
}  // namespace matc
