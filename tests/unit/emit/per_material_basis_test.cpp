// A basis per material (--basis auto): the rule, the table's layers side by side, the library's
// functions per layer and each snippet calling its own, against one-basis builds of each basis.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "compile/basis_choice.h"
#include "compile/compile.h"
#include "emit/build.h"
#include "lut/preintegrate.h"
#include "matc/runtime/lut.h"
#include "material/parse.h"
#include "optics/presets.h"
#include "preset_material.h"

namespace matc {
namespace {

constexpr std::string_view kF82Tint =
    R"({"name": "tinted", "f82_tint": {"f0": [0.9, 0.6, 0.3], "tint": [0.5, 0.8, 1.0]}})";

Material parsed(std::string_view json, std::string_view file = "m.json") {
  const ParseResult result = parse_material(std::string(json), std::string(file));
  if (!result.material) throw std::runtime_error("material does not parse");
  return *result.material;
}

BuildOptions small_options(bool per_material, runtime::BasisKind basis = runtime::kDefaultBasis) {
  BuildOptions options;
  options.lut = {16, 64, 0};
  options.basis = basis;
  options.per_material_basis = per_material;
  return options;
}

TEST(BasisChoice, BareF82TintMetalsTakeF82AndEveryOtherCurvePowers) {
  const Material tinted = parsed(kF82Tint);
  EXPECT_EQ(per_material_basis(tinted), runtime::BasisKind::f82);
  EXPECT_EQ(per_material_basis(test::preset_material(*find_metal_preset("Au"), "gold")),
            runtime::BasisKind::powers);
  EXPECT_EQ(per_material_basis(
                parsed(R"({"name": "g", "artistic": {"reflectivity": 0.9, "edge_tint": 0.5}})")),
            runtime::BasisKind::powers);
  // Under a coat the curve is no longer F82-tint's.
  EXPECT_EQ(per_material_basis(parsed(
                R"({"name": "c", "f82_tint": {"f0": 0.9, "tint": 0.5}, "coat": {"ior": 1.5}})")),
            runtime::BasisKind::powers);
  // A pin wins; --basis NAME wins over both.
  const Material pinned =
      parsed(R"({"name": "p", "f82_tint": {"f0": 0.9, "tint": 0.5}, "basis": "powers"})");
  EXPECT_EQ(per_material_basis(pinned), runtime::BasisKind::powers);
  EXPECT_EQ(chosen_basis(tinted, {runtime::BasisKind::extended, false}),
            runtime::BasisKind::extended);
  EXPECT_EQ(chosen_basis(tinted, {runtime::BasisKind::powers, true}), runtime::BasisKind::f82);
}

TEST(PerMaterialBuild, TheTableHoldsEachBasisTableSideBySide) {
  const Build layered(small_options(true));
  ASSERT_EQ(layered.lut_layers().size(), 2u);
  const LutAtlas& atlas = layered.stored_atlas();
  EXPECT_EQ(atlas.width(), 32u);
  EXPECT_EQ(atlas.size, 16u);
  // Each layer is bit for bit the table of a one-basis build of its basis.
  for (std::size_t layer = 0; layer < 2; ++layer) {
    const runtime::BasisKind basis = layered.lut_layers()[layer];
    const Build alone(small_options(false, basis));
    const Lut& table = alone.stored_lut();
    EXPECT_EQ(layered.stored_lut(basis).texels, table.texels);
    for (std::size_t y = 0; y < atlas.size; ++y) {
      for (std::size_t x = 0; x < atlas.size; ++x) {
        for (std::size_t c = 0; c < 4; ++c) {
          ASSERT_EQ(atlas.texels[((y * atlas.width()) + layer * atlas.size + x) * 4 + c],
                    table.texels[(y * atlas.size + x) * 4 + c]);
        }
      }
    }
  }
  EXPECT_EQ(layered.lut_layer(runtime::BasisKind::f82), 1u);
  EXPECT_THROW((void)layered.lut_layer(runtime::BasisKind::paper), std::invalid_argument);
  // The layers differ where a wrong layer would show: a shader reading powers' bbar for an f82
  // material would be far off.
  const runtime::LutView powers = layered.stored_lut(runtime::BasisKind::powers).view();
  const runtime::LutView f82 = layered.stored_lut(runtime::BasisKind::f82).view();
  EXPECT_GT(
      std::abs(runtime::sample_lut(powers, 0.5, 0.3)[2] - runtime::sample_lut(f82, 0.5, 0.3)[2]),
      0.01);
}

TEST(PerMaterialBuild, EachMaterialIsCompiledAgainstItsBasisAndItsSnippetCallsIt) {
  const Build build(small_options(true));
  const Material tinted = parsed(kF82Tint);
  const CompiledMaterial compiled = compile_material(tinted, build.basis_for(tinted));
  EXPECT_EQ(compiled.basis, runtime::BasisKind::f82);
  EXPECT_LE(compiled.accuracy.decomposition.max_abs[0], 1e-12);  // F82-tint is in f82's span
  for (const ShaderLanguage language : kShaderLanguages) {
    const std::string library = build.library_source(language);
    EXPECT_NE(library.find("matc_fresnel_f82"), std::string::npos);
    EXPECT_NE(library.find("matc_lut_texcoord_f82"), std::string::npos);
    EXPECT_NE(library.find("matc_preintegrated_basis_analytic_f82"), std::string::npos);
    EXPECT_NE(library.find("matc_ltc_following_f82("), std::string::npos);
    EXPECT_NE(library.find("matc_ltc_quad_light_following_f82("), std::string::npos);
    const std::string snippet = build.material_source(language, compiled);
    EXPECT_TRUE(snippet.find("matc_fresnel_sum_f82(") != std::string::npos ||
                snippet.find("matc_fresnel_f82(") != std::string::npos)
        << snippet;
    EXPECT_NE(snippet.find("matc_lut_texcoord_tinted"), std::string::npos);
  }
  const Material gold = test::preset_material(*find_metal_preset("Au"), "gold");
  const CompiledMaterial powers = compile_material(gold, build.basis_for(gold));
  EXPECT_EQ(powers.basis, runtime::BasisKind::powers);
  EXPECT_EQ(build.material_source(ShaderLanguage::glsl, powers).find("_f82"), std::string::npos);
  // Its module is compiled through glslang (no checked-in template holds a per-material build's
  // snippet); device_validation_test runs both front ends' kernels on lavapipe.
  EXPECT_FALSE(build.material_library_module(compiled).empty());
}

TEST(PerMaterialBuild, OneBasisBuildsAreUnchanged) {
  const Build forced(small_options(false));
  const Material tinted = parsed(kF82Tint);
  EXPECT_EQ(forced.basis_for(tinted).kind, runtime::BasisKind::powers);
  EXPECT_EQ(forced.lut_layers().size(), 1u);
  EXPECT_EQ(forced.library_source(ShaderLanguage::glsl).find("MATC_LUT_LAYERS"), std::string::npos);
  const CompiledMaterial compiled = compile_material(tinted, forced.basis_for(tinted));
  EXPECT_EQ(forced.material_source(ShaderLanguage::glsl, compiled).find("matc_lut_texcoord_tinted"),
            std::string::npos);
}

// The first layer is powers': a per-material build that names another first basis is refused.
TEST(PerMaterialBuild, AFirstBasisOtherThanPowersIsRefused) {
  EXPECT_THROW(Build{small_options(true, runtime::BasisKind::f82)}, std::invalid_argument);
}

// --embed-lut embeds each layer as its own array: the first basis' under the first layer's names,
// f82's under its suffix, each exactly that basis' table at the embedded size (an F82-tint
// material's snippet reads the second).
TEST(PerMaterialBuild, EmbedsEachLayersTable) {
  BuildOptions options = small_options(true);
  options.embedded_lut_size = 8;
  const Build build(options);
  for (const runtime::BasisKind basis : runtime::kPerMaterialBases) {
    const Lut* embedded = build.embedded_lut(basis);
    ASSERT_NE(embedded, nullptr);
    EXPECT_EQ(embedded->size, 8u);
    EXPECT_EQ(embedded->texels, preintegrate_lut(runtime::shipped_basis(basis), {8, 64}).texels);
  }
  EXPECT_NE(build.embedded_lut(runtime::BasisKind::powers)->texels,
            build.embedded_lut(runtime::BasisKind::f82)->texels);
  for (const ShaderLanguage language : kShaderLanguages) {
    const std::string& library = build.library_source(language);
    EXPECT_NE(library.find("matc_preintegrated_basis_embedded("), std::string::npos);
    EXPECT_NE(library.find("matc_preintegrated_basis_embedded_f82("), std::string::npos);
    EXPECT_NE(library.find("MATC_EMBEDDED_LUT_f82"), std::string::npos);
  }
}

// The C++ header of the table holds both layers side by side, with their count and bases.
TEST(PerMaterialBuild, TheHeaderHoldsEveryLayer) {
  BuildOptions options = small_options(true);
  options.lut_format = LutFormat::header;
  const Build build(options);
  bool found = false;
  for (const OutputFile& file : build.shared_outputs()) {
    if (file.name != "matc_lut.h") continue;
    found = true;
    EXPECT_NE(file.bytes.find("kLayers = 2;"), std::string::npos);
    EXPECT_NE(file.bytes.find("kLayerBases[kLayers] = {\"powers\", \"f82\"};"), std::string::npos);
    EXPECT_NE(file.bytes.find("kTexels[2048]"), std::string::npos);  // 32 x 16 texels x 4
  }
  EXPECT_TRUE(found);
}

TEST(PerMaterialBuild, TheManifestNamesEachLayer) {
  const Build build(small_options(true));
  const nlohmann::ordered_json description = build.description();
  EXPECT_EQ(description["basis"], "auto");
  EXPECT_EQ(description["lut_layers"], nlohmann::ordered_json::array({"powers", "f82"}));
  bool found = false;
  for (const OutputFile& file : build.shared_outputs()) {
    if (file.name != "matc_lut.ktx2.json") continue;
    found = true;
    const auto manifest = nlohmann::json::parse(file.bytes);
    EXPECT_EQ(manifest["size"], nlohmann::json::array({32, 16}));
    EXPECT_EQ(manifest["layers"][1]["basis"], "f82");
    EXPECT_EQ(manifest["layers"][1]["columns"], nlohmann::json::array({16, 31}));
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace matc
