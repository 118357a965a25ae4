// The glTF importer: the metal's mapping (Schlick's curve from baseColorFactor, the F82 edge
// colour, the clear coat and its index), the notes for what is not carried, .glb against .gltf,
// and the asset checks (GLB layout, buffers and their URIs, buffer views, accessors, images).
#include <gtest/gtest.h>

#include <cstring>
#include <map>

#include <fmt/format.h>

#include "compile/compile.h"
#include "diagnostic_text.h"
#include "glb_bytes.h"
#include "matc/runtime/fresnel.h"
#include "material/gltf_import.h"
#include "optics/fresnel.h"

namespace matc {
namespace {

std::string all_diagnostics(const DocumentImport& imported) {
  return test::diagnostic_text(imported.diagnostics);
}

std::string asset(const std::string& materials, const std::string& rest = "") {
  return R"({"asset": {"version": "2.0"}, "materials": [)" + materials + "]" + rest + "}";
}

const std::string kCarPaint = R"({"name": "CarPaint",
  "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.05, 0.04, 1], "roughnessFactor": 0.35},
  "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 0.9, "clearcoatRoughnessFactor": 0.05,
    "extensions": {"KHR_materials_clearcoat_ior": {"clearcoatIor": 1.6}}}}})";

// A loader serving files from memory (name -> bytes), recording what was asked.
struct MemoryFiles {
  std::map<std::string, std::string> files;
  std::vector<std::string> asked;
  FileLoader loader() {
    return [this](const std::filesystem::path& path, std::uintmax_t) {
      asked.push_back(path.generic_string());
      const auto found = files.find(path.generic_string());
      if (found == files.end()) return LoadedFile{std::nullopt, "no such file"};
      return LoadedFile{found->second, {}};
    };
  }
};

// The asset as a GLB: header, the JSON chunk (padded with spaces), an optional BIN chunk.
std::string glb(const std::string& json, const std::string& bin = "") {
  return test::glb_bytes(json, bin);
}

TEST(GltfImport, ACoreMetalIsSchlicksCurveFromItsBaseColour) {
  const auto imported = import_gltf(
      asset(R"({"name": "gold", "pbrMetallicRoughness": {"baseColorFactor": [1, 0.78, 0.34, 1],
               "metallicFactor": 1, "roughnessFactor": 0.3}})"),
      "a.gltf");
  ASSERT_EQ(imported.materials.size(), 1u) << all_diagnostics(imported);
  EXPECT_EQ(all_diagnostics(imported), "");
  const Material& material = imported.materials[0].material;
  EXPECT_EQ(material.name, "gold");
  ASSERT_TRUE(material.roughness);
  EXPECT_DOUBLE_EQ(*material.roughness, 0.3);
  // The exact curve the compile fits is Schlick's from F0 (F82-tint with a white tint): its
  // Schlick error is 0, and the compiled curve is Schlick's within the fit's own error.
  const auto compiled = compile_material(material, runtime::shipped_basis());
  const Rgb f0{1, 0.78, 0.34};
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_LT(compiled.accuracy.schlick.max_abs[c], 1e-12);
  for (double mu = 0; mu <= 1.0; mu += 0.01) {
    const Rgb f = runtime::evaluate_fresnel(compiled.coefficients, runtime::shipped_basis(), mu);
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_LE(std::abs(f[c] - fresnel_schlick(mu, f0[c])),
                compiled.accuracy.decomposition.max_abs[c] + 1e-9)
          << mu;
  }
}

TEST(GltfImport, AClearCoatBecomesTheMaterialsCoatWithItsIndex) {
  const auto imported = import_gltf(asset(kCarPaint), "car.gltf");
  ASSERT_EQ(imported.materials.size(), 1u) << all_diagnostics(imported);
  const auto& coat = imported.materials[0].material.coat;
  ASSERT_TRUE(coat);
  EXPECT_DOUBLE_EQ(coat->weight, 0.9);
  EXPECT_DOUBLE_EQ(coat->ior, 1.6);
  EXPECT_DOUBLE_EQ(coat->roughness, 0.05);
  EXPECT_NE(imported.materials[0].json.find("\"coat\""), std::string::npos);
}

TEST(GltfImport, TheSpecularEdgeColourIsTheF82TintOnlyWhenEnabled) {
  const std::string specular = R"("KHR_materials_specular": {"specularFactor": 0.5,
    "specularColorFactor": [0.8, 1.6, 1.0], "extensions": {"EXT_materials_specular_edge_color":
    {"specularEdgeColorEnabled": )";
  const auto enabled =
      import_gltf(asset(R"({"name": "m", "extensions": {)" + specular + "true}}}}}"), "a.gltf");
  ASSERT_EQ(enabled.materials.size(), 1u) << all_diagnostics(enabled);
  const auto& tint = std::get<F82TintInput>(enabled.materials[0].material.model).tint;
  EXPECT_DOUBLE_EQ(tint[0], 0.4);
  EXPECT_DOUBLE_EQ(tint[1], 0.8);
  EXPECT_DOUBLE_EQ(tint[2], 0.5);
  const auto disabled =
      import_gltf(asset(R"({"name": "m", "extensions": {)" + specular + "false}}}}}"), "a.gltf");
  ASSERT_EQ(disabled.materials.size(), 1u);
  const auto& white = std::get<F82TintInput>(disabled.materials[0].material.model).tint;
  EXPECT_EQ(white, (Rgb{1, 1, 1}));
}

TEST(GltfImport, WhatIsNotCarriedGetsANoteNamingTheMaterialAndTheProperty) {
  const auto imported =
      import_gltf(asset(R"({"name": "Foil", "pbrMetallicRoughness": {"metallicFactor": 0.6,
                 "baseColorTexture": {"index": 0}},
                 "extensions": {"KHR_materials_iridescence": {"iridescenceFactor": 1}}},
               {"name": "Rubber", "pbrMetallicRoughness": {"metallicFactor": 0}})",
                        R"(, "textures": [{"source": 0}], "images": [{"uri": "foil.png"}])"),
                  "a.glb.gltf");
  ASSERT_EQ(imported.materials.size(), 1u) << all_diagnostics(imported);
  const std::string text = all_diagnostics(imported);
  EXPECT_NE(text.find("a.glb.gltf: note: materials[0] \"Foil\": not carried: partial metalness "
                      "(metallicFactor 0.6"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("baseColorTexture"), std::string::npos);
  // The film makes the curve's shape depend on F0: the texture goes through the F0 table.
  EXPECT_NE(text.find("under a thin film the curve is not linear in F0"), std::string::npos)
      << text;
  ASSERT_TRUE(imported.materials[0].material.film.has_value());
  EXPECT_TRUE(imported.materials[0].f0_table);
  EXPECT_NE(text.find("materials[1] \"Rubber\": not imported: not a metal"), std::string::npos);
}

// A pipeline sees every asset: one without a metal is valid, with nothing to compile.
TEST(GltfImport, AnAssetWithoutAMetalImportsNothingWithANote) {
  const auto imported =
      import_gltf(asset(R"({"pbrMetallicRoughness": {"metallicFactor": 0}})"), "plastic.gltf");
  EXPECT_TRUE(imported.materials.empty());
  EXPECT_FALSE(imported.diagnostics.has_errors());
  EXPECT_NE(all_diagnostics(imported).find(
                "plastic.gltf: note: holds no metal (none of its 1 materials has metallicFactor "
                "above 0): nothing for matc to compile"),
            std::string::npos)
      << all_diagnostics(imported);
  const auto empty = import_gltf(R"({"asset": {"version": "2.0"}})", "empty.gltf");
  EXPECT_TRUE(empty.materials.empty());
  EXPECT_FALSE(empty.diagnostics.has_errors()) << all_diagnostics(empty);
}

// glTF's names need not be unique (they name files in matc): a clash ignoring case, after
// sanitising, or with an unnamed material's `material_<index>` takes a derived name with a note,
// never one a later material holds itself, never with "__", at most 64 characters.
TEST(GltfImport, CollidingNamesTakeDerivedUniqueNames) {
  const std::string long_name(70, 'x');
  const auto imported = import_gltf(
      asset(R"({"name": "Gold"}, {"name": "gold"}, {"name": "gold_2"}, {"name": "Metal 1"},
               {"name": "Metal_1"}, {}, {"name": "material_5"}, {"name": "Trim_"}, {"name": "trim_"},
               {"name": ")" +
            long_name + R"("}, {"name": ")" + long_name + R"(y"}, {"name": "Gold"})"),
      "a.gltf");
  ASSERT_FALSE(imported.diagnostics.has_errors()) << all_diagnostics(imported);
  std::vector<std::string> names;
  for (const ImportedMaterial& material : imported.materials)
    names.push_back(material.material.name);
  const std::string x64(64, 'x');
  EXPECT_EQ(names, (std::vector<std::string>{"Gold", "gold_3", "gold_2", "Metal_1", "Metal_1_2",
                                             "material_5", "material_5_2", "Trim_", "trim_2", x64,
                                             x64.substr(0, 62) + "_2", "Gold_4"}));
  EXPECT_NE(all_diagnostics(imported).find(
                "a.gltf: note: materials[1] \"gold\": imported as 'gold_3': 'gold' is 'Gold' "
                "(materials[0] \"Gold\") ignoring case"),
            std::string::npos)
      << all_diagnostics(imported);
  for (std::size_t i = 0; i < imported.materials.size(); ++i)
    EXPECT_EQ(imported.materials[i].document_index, i);
}

// A glTF material named like a file every build writes once (matc_lut.ktx2, matc_fresnel.glsl,
// matc_manifest.json, in any case) takes a derived name with a note: valid glTF, imported.
// KHR_materials_iridescence on a metal is the material's film: coverage iridescenceFactor, index
// iridescenceIor (1.3), thickness iridescenceThicknessMaximum (400 nm), as the extension's film is
// without its thickness texture, whose per-pixel thickness is named as not carried.
TEST(GltfImport, IridescenceBecomesTheFilm) {
  const auto metal = [](const std::string& iridescence, const std::string& rest = "") {
    return import_gltf(
        asset(R"({"name": "Trim", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.45, 1]},
                  "extensions": {"KHR_materials_iridescence": )" +
              iridescence + rest + "}}"),
        "a.gltf");
  };
  const auto given = metal(
      R"({"iridescenceFactor": 0.75, "iridescenceIor": 2.2, "iridescenceThicknessMinimum": 50,
          "iridescenceThicknessMaximum": 300})");
  ASSERT_EQ(given.materials.size(), 1u) << all_diagnostics(given);
  ASSERT_TRUE(given.materials[0].material.film.has_value());
  EXPECT_EQ(given.materials[0].material.film->weight, 0.75);
  EXPECT_EQ(given.materials[0].material.film->ior, 2.2);
  EXPECT_EQ(given.materials[0].material.film->thickness_nm, 300.0);
  EXPECT_EQ(all_diagnostics(given), "");

  const auto defaults = metal(R"({"iridescenceFactor": 1})");
  ASSERT_EQ(defaults.materials.size(), 1u) << all_diagnostics(defaults);
  EXPECT_EQ(defaults.materials[0].material.film->ior, 1.3);
  EXPECT_EQ(defaults.materials[0].material.film->thickness_nm, 400.0);

  const auto off = metal(R"({"iridescenceIor": 1.5})");  // the factor's default is 0
  ASSERT_EQ(off.materials.size(), 1u) << all_diagnostics(off);
  EXPECT_FALSE(off.materials[0].material.film.has_value());

  const auto textured =
      metal(R"({"iridescenceFactor": 1, "iridescenceThicknessTexture": {"index": 0}})");
  ASSERT_EQ(textured.materials.size(), 1u) << all_diagnostics(textured);
  EXPECT_NE(all_diagnostics(textured).find("iridescenceThicknessTexture (compiled at "
                                           "iridescenceThicknessMaximum, 400 nm"),
            std::string::npos)
      << all_diagnostics(textured);

  const auto dense = metal(R"({"iridescenceFactor": 1, "iridescenceIor": 3.5})");
  ASSERT_EQ(dense.materials.size(), 1u) << all_diagnostics(dense);
  EXPECT_EQ(dense.materials[0].material.film->ior, kMaxFilmIor);
  EXPECT_NE(all_diagnostics(dense).find("iridescenceIor 3.5 clamped to 3"), std::string::npos);

  // Under a clear coat the film is carried, under the coat. One of index 1, which the extension's
  // formula shows as nothing, is left out: under a coat it would be an air gap.
  const auto coated = import_gltf(
      asset(
          R"({"name": "Trim", "extensions": {"KHR_materials_iridescence": {"iridescenceFactor": 1},
                "KHR_materials_clearcoat": {"clearcoatFactor": 1}}})"),
      "a.gltf");
  ASSERT_EQ(coated.materials.size(), 1u) << all_diagnostics(coated);
  ASSERT_TRUE(coated.materials[0].material.film.has_value());
  EXPECT_EQ(coated.materials[0].material.film->ior, 1.3);
  EXPECT_TRUE(coated.materials[0].material.coat.has_value());
  const auto air_gap =
      import_gltf(asset(R"({"name": "Trim", "extensions": {"KHR_materials_iridescence":
                {"iridescenceFactor": 1, "iridescenceIor": 1},
                "KHR_materials_clearcoat": {"clearcoatFactor": 1}}})"),
                  "a.gltf");
  ASSERT_EQ(air_gap.materials.size(), 1u) << all_diagnostics(air_gap);
  EXPECT_FALSE(air_gap.materials[0].material.film.has_value());
  EXPECT_TRUE(air_gap.materials[0].material.coat.has_value());

  // What matc cannot compile is a located error naming the property.
  for (const auto& [bad, message] : std::vector<std::pair<std::string, std::string>>{
           {R"({"iridescenceFactor": 1.5})", "iridescenceFactor is 1.5"},
           {R"({"iridescenceFactor": 1, "iridescenceThicknessMaximum": 5000})",
            "iridescenceThicknessMaximum is 5000"},
           {R"({"iridescenceFactor": 1, "iridescenceThicknessMinimum": -1})",
            "iridescenceThicknessMinimum is -1"},
           {R"({"iridescenceFactor": 1, "iridescenceIor": 0.9})", "iridescenceIor is 0.9"},
           {R"({"iridescenceFactor": "1"})", "iridescenceFactor is not a number"}}) {
    const auto refused = metal(bad);
    EXPECT_TRUE(refused.materials.empty()) << bad;
    EXPECT_NE(all_diagnostics(refused).find(message), std::string::npos)
        << bad << ": " << all_diagnostics(refused);
  }
}

// extras.matc_basis pins the material's basis (material/basis_pin.h), as "basis" in a file does.
TEST(GltfImport, ABasisPinInExtrasIsTheMaterialFilesBasis) {
  const auto metal = [](const std::string& extras) {
    return import_gltf(asset(R"({"name": "Trim", "pbrMetallicRoughness": {"baseColorFactor":
                                 [0.9, 0.6, 0.3, 1]})" +
                             extras + "}"),
                       "a.gltf");
  };
  const auto unpinned = metal(R"(, "extras": {"author": "x"})");
  ASSERT_EQ(unpinned.materials.size(), 1u) << all_diagnostics(unpinned);
  EXPECT_FALSE(unpinned.materials[0].material.basis.has_value());
  for (const runtime::BasisKind basis : runtime::kPerMaterialBases) {
    const auto imported =
        metal(fmt::format(R"(, "extras": {{"matc_basis": "{}"}})", runtime::basis_name(basis)));
    ASSERT_EQ(imported.materials.size(), 1u) << all_diagnostics(imported);
    EXPECT_EQ(imported.materials[0].material.basis, basis);
  }
  const auto refused = metal(R"(, "extras": {"matc_basis": "paper"})");
  EXPECT_TRUE(refused.materials.empty());
  EXPECT_NE(all_diagnostics(refused).find("extras.matc_basis: 'paper' is a fitted basis"),
            std::string::npos)
      << all_diagnostics(refused);
}

TEST(GltfImport, NamesOfSharedFilesTakeDerivedNames) {
  const auto imported = import_gltf(
      asset(R"({"name": "matc_lut"}, {"name": "MATC_Fresnel"}, {"name": "matc_manifest"},
               {"name": "matc_lut_2"})"),
      "a.gltf");
  ASSERT_FALSE(imported.diagnostics.has_errors()) << all_diagnostics(imported);
  std::vector<std::string> names;
  for (const ImportedMaterial& material : imported.materials)
    names.push_back(material.material.name);
  EXPECT_EQ(names, (std::vector<std::string>{"matc_lut_3", "MATC_Fresnel_2", "matc_manifest_2",
                                             "matc_lut_2"}));
  EXPECT_NE(all_diagnostics(imported).find(
                "a.gltf: note: materials[0] \"matc_lut\": imported as 'matc_lut_3': 'matc_lut' "
                "names the files every build writes once (matc_lut.*) ignoring case"),
            std::string::npos)
      << all_diagnostics(imported);
}

TEST(GltfImport, ValuesOutsideGltfsOrMatcsRangesAreErrors) {
  for (const auto& [material, phrase] : std::vector<std::pair<std::string, std::string>>{
           {R"({"pbrMetallicRoughness": {"baseColorFactor": [1.2, 0.5, 0.5, 1]}})",
            "pbrMetallicRoughness.baseColorFactor[0] is 1.2; [0, 1]"},
           {R"({"pbrMetallicRoughness": {"roughnessFactor": -0.5}})",
            "pbrMetallicRoughness.roughnessFactor is -0.5; [0, 1]"},
           {R"({"extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1, "extensions":
                {"KHR_materials_clearcoat_ior": {"clearcoatIor": 1.01}}}}})",
            "KHR_materials_clearcoat_ior.clearcoatIor is 1.01; a coat index in [1.05, 3]"},
           {R"({"extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": "full"}}})",
            "KHR_materials_clearcoat: clearcoatFactor is not a number"},
       }) {
    const auto imported = import_gltf(asset(material), "a.gltf");
    EXPECT_TRUE(imported.materials.empty()) << material;
    EXPECT_NE(all_diagnostics(imported).find(phrase), std::string::npos)
        << all_diagnostics(imported);
  }
}

TEST(GltfImport, AGlbImportsAsItsJsonDoes) {
  const std::string json = asset(kCarPaint,
                                 R"(, "buffers": [{"byteLength": 12}],
      "bufferViews": [{"buffer": 0, "byteLength": 12}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 1, "type": "VEC3"}])");
  const auto binary = import_gltf(glb(json, std::string(12, '\0')), "car.glb");
  ASSERT_EQ(binary.materials.size(), 1u) << all_diagnostics(binary);
  // The extension in any case, as every reader takes it.
  EXPECT_EQ(import_gltf(glb(json, std::string(12, '\0')), "CAR.Glb").materials.size(), 1u);
  const auto text = import_gltf(asset(kCarPaint), "car.gltf");
  ASSERT_EQ(text.materials.size(), 1u);
  EXPECT_EQ(binary.materials[0].json.substr(binary.materials[0].json.find("\"color_space\"")),
            text.materials[0].json.substr(text.materials[0].json.find("\"color_space\"")));
}

TEST(GltfImport, ABrokenGlbContainerIsRefusedBeforeItIsRead) {
  const std::string good = glb(asset(kCarPaint), std::string(8, '\0'));
  for (const auto& [bytes, phrase] : std::vector<std::pair<std::string, std::string>>{
           {good.substr(0, good.size() - 4), "the GLB header says"},
           {good.substr(0, 16), "shorter than a GLB header"},
           {"glTX" + good.substr(4), "does not start with the GLB magic"},
       }) {
    const auto imported = import_gltf(bytes, "car.glb");
    EXPECT_TRUE(imported.materials.empty());
    EXPECT_NE(all_diagnostics(imported).find(phrase), std::string::npos)
        << all_diagnostics(imported);
  }
  // A BIN chunk that says it runs past the file (tinygltf alone would read 8 bytes past it).
  std::string past = good;
  const std::size_t bin_header = past.size() - 8 - 8;
  past[bin_header] = 16;
  EXPECT_NE(
      all_diagnostics(import_gltf(past, "car.glb")).find("the BIN chunk (16 bytes) runs past"),
      std::string::npos);
}

TEST(GltfImport, BuffersAreReadOnlyFromInsideTheAssetsFolder) {
  MemoryFiles files;
  files.files["assets/car.bin"] = std::string(12, '\0');
  const std::string views = R"(, "bufferViews": [{"buffer": 0, "byteLength": 12}])";
  const auto inside = import_gltf(
      asset(kCarPaint, R"(, "buffers": [{"byteLength": 12, "uri": "car.bin"}])" + views),
      "assets/car.gltf", files.loader());
  EXPECT_EQ(inside.materials.size(), 1u) << all_diagnostics(inside);
  EXPECT_EQ(files.asked, std::vector<std::string>{"assets/car.bin"});
  for (const std::string uri :
       {"../secret.bin", "/etc/passwd", "sub/../../x.bin", "file:///etc/passwd", "%2e%2e/x.bin"}) {
    files.asked.clear();
    const auto outside = import_gltf(
        asset(kCarPaint, R"(, "buffers": [{"byteLength": 12, "uri": ")" + uri + "\"}]" + views),
        "assets/car.gltf", files.loader());
    EXPECT_TRUE(outside.materials.empty()) << uri;
    EXPECT_TRUE(files.asked.empty()) << uri << " read " << files.asked.front();
    EXPECT_NE(all_diagnostics(outside).find("assets/car.gltf: error: "), std::string::npos) << uri;
  }
  const auto missing =
      import_gltf(asset(kCarPaint, R"(, "buffers": [{"byteLength": 12, "uri": "gone.bin"}])"),
                  "assets/car.gltf", files.loader());
  EXPECT_NE(all_diagnostics(missing).find("cannot read buffer 'gone.bin': no such file"),
            std::string::npos)
      << all_diagnostics(missing);
}

TEST(GltfImport, RangesAndCountsAreChecked) {
  const std::string buffer =
      R"(, "buffers": [{"byteLength": 12, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAIA/"}])";
  for (
      const auto& [rest, phrase] : std::vector<std::pair<std::string, std::string>>{
          {buffer + R"(, "bufferViews": [{"buffer": 0, "byteOffset": 8, "byteLength": 8}])",
           "bufferViews[0]: bytes 8 to 16 of buffer 0, which has 12"},
          {buffer + R"(, "bufferViews": [{"buffer": 3, "byteLength": 4}])",
           "bufferViews[0]: buffer 3 does not exist"},
          {buffer + R"(, "bufferViews": [{"buffer": 0, "byteLength": 12}], "accessors":
              [{"bufferView": 0, "componentType": 5126, "count": 2, "type": "VEC3"}])",
           "accessors[0]: needs bytes 0 to 24 of bufferView 0, which has 12"},
          {R"(, "accessors": [{"componentType": 5126, "count": 4000000000, "type": "MAT4"}])",
           "accessors[0]: count 4000000000 of 64-byte elements"},
          {R"(, "images": [{"uri": "../../photo.png"}])",
           "images[0]: uri '../../photo.png': a path that leaves the asset's folder"},
          {R"(, "buffers": [{"byteLength": 4, "uri": "data:application/octet-stream;base64,@@@@"}])",
           "a.gltf: error: "},
          {R"(, "buffers": [{"byteLength": 4, "uri": "data:text/plain,abcd"}])", "a.gltf: error: "},
      }) {
    const auto imported = import_gltf(asset(kCarPaint, rest), "a.gltf");
    EXPECT_TRUE(imported.materials.empty()) << rest;
    EXPECT_NE(all_diagnostics(imported).find(phrase), std::string::npos)
        << rest << "\n"
        << all_diagnostics(imported);
  }
}

TEST(GltfImport, DiagnosticsNeverEchoControlBytes) {
  const auto imported =
      import_gltf(asset(R"({"name": "evil\u001b[2J\nmatc: error: forged", "pbrMetallicRoughness":
               {"roughnessFactor": 7}})"),
                  "a.gltf");
  const std::string text = all_diagnostics(imported);
  EXPECT_EQ(text.find('\x1b'), std::string::npos);
  EXPECT_EQ(text.find("\nmatc: error: forged"), std::string::npos) << text;
}

}  // namespace
}  // namespace matc
