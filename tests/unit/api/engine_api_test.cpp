// The public API's pieces an engine or a maintainer reaches for beside compiling: Gulbrandsen's
// mapping (api/compiled_material.h), SPIR-V linking (api/spirv.h) and the checked-in sources made
// again (api/regeneration.h). Each is the module's own, and each refuses bad arguments by name.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "matc/api/build.h"
#include "matc/api/options.h"
#include "matc/api/regeneration.h"
#include "matc/api/spirv.h"
#include "matc/matc.h"
#include "optics/gulbrandsen.h"

namespace {

std::string read_source(const std::string& path) {
  std::ifstream in(std::string(MATC_SOURCE_DIR) + "/" + path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string thrown_by(const auto& call) {
  try {
    call();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "nothing thrown";
}

TEST(GulbrandsenApi, IsTheModulesMappingPerChannelBothWays) {
  const matc::api::ArtisticParameters artistic{{0.95, 0.5, 0.0}, {0.1, 0.9, 0.5}};
  const matc::api::ComplexIor ior = matc::api::ior_from_artistic(artistic);
  for (std::size_t c = 0; c < 3; ++c) {
    const matc::ComplexIor expected =
        matc::gulbrandsen_to_ior({artistic.reflectivity[c], artistic.edge_tint[c]});
    EXPECT_EQ(ior.n[c], expected.n);
    EXPECT_EQ(ior.k[c], expected.k);
  }
  const matc::api::ArtisticParameters back = matc::api::artistic_from_ior(ior);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(back.reflectivity[c], artistic.reflectivity[c], 1e-12);
    if (artistic.reflectivity[c] > 0.0) {
      EXPECT_NEAR(back.edge_tint[c], artistic.edge_tint[c], 1e-9);
    }
  }
}

TEST(GulbrandsenApi, RefusesValuesOutsideTheMappingByFieldAndChannel) {
  EXPECT_EQ(thrown_by([] {
              matc::api::ior_from_artistic({{0.5, 1.0, 0.5}, {0.5, 0.5, 0.5}});
            }),
            "reflectivity: element 1 is 1; a number in [0, 1)");
  EXPECT_EQ(thrown_by([] {
              matc::api::ior_from_artistic({{0.5, 0.5, 0.5}, {0.5, 0.5, NAN}});
            }),
            "edge_tint: element 2 is nan; a number in [0, 1]");
  EXPECT_EQ(thrown_by([] {
              matc::api::artistic_from_ior({{0.0, 1.0, 1.0}, {1.0, 1.0, 1.0}});
            }),
            "n: element 0 is 0; a finite number above 0");
  EXPECT_EQ(thrown_by([] {
              matc::api::artistic_from_ior({{1.0, 1.0, 1.0}, {1.0, -1.0, 1.0}});
            }),
            "k: element 1 is -1; a finite number, 0 or above");
}

// What examples/engine does: its shader declares matc_fresnel_<name> with a placeholder body,
// imports it, and links the material's library module, which a build writes.
TEST(SpirvApi, LinksAnEngineShaderToAMaterialsLibraryModule) {
  matc::api::BuildOptions options;
  options.emit = {"spirv"};
  const matc::api::Build build(options);
  const matc::api::Material material = matc::api::parse_material_json(
      R"({"name": "gold", "ior": {"n": [0.18, 0.42, 1.37], "k": [3.42, 2.35, 1.77]}})", "gold");
  const std::vector<matc::api::OutputFile> files = build.material_files(build.compile(material));
  const auto library_file = std::find_if(files.begin(), files.end(),
                                         [](const auto& file) { return file.name == "gold.spv"; });
  ASSERT_NE(library_file, files.end());
  ASSERT_EQ(library_file->bytes.size() % 4, 0u);
  matc::api::SpirvWords library(library_file->bytes.size() / 4);
  std::memcpy(library.data(), library_file->bytes.data(), library_file->bytes.size());

  const std::string shader = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { vec4 values[]; };
vec3 matc_fresnel_gold(float mu) { return vec3(0.0); }
void main() { values[gl_GlobalInvocationID.x].rgb = matc_fresnel_gold(values[0].x); }
)";
  const std::vector<std::string> imports = {"matc_fresnel_gold"};
  const matc::api::SpirvWords engine = matc::api::import_functions(
      matc::api::compile_shader("glsl", shader, "engine.comp"), imports);
  const std::vector<matc::api::SpirvWords> modules = {engine, library};
  const matc::api::SpirvWords linked = matc::api::link_spirv(modules, "engine+gold");
  EXPECT_GT(linked.size(), engine.size());
  // Without the library the import stays unresolved: the linker says so.
  const std::vector<matc::api::SpirvWords> alone = {engine};
  EXPECT_THROW(matc::api::link_spirv(alone, "engine alone"), std::runtime_error);
}

TEST(SpirvApi, RefusesUnknownNamesAndShowsCompileErrorsAtTheirLine) {
  EXPECT_EQ(thrown_by([] { matc::api::compile_shader("wgsl", "", "x"); }),
            "language: 'wgsl' is not one of glsl, hlsl (WGSL is not compiled to SPIR-V here)");
  EXPECT_EQ(thrown_by([] { matc::api::compile_shader("glsl", "", "x", "geometry"); }),
            "stage: 'geometry' is not one of compute, vertex, fragment");
  const matc::api::SpirvWords module = matc::api::compile_shader(
      "glsl", "#version 450\nlayout(local_size_x = 1) in;\nvoid main() {}\n", "empty.comp");
  const std::vector<std::string> missing = {"no\nsuch"};
  EXPECT_EQ(thrown_by([&] { matc::api::import_functions(module, missing); }),
            "SPIR-V module has no function 'no\\nsuch'");
  try {
    matc::api::compile_shader("glsl", "#version 450\nvoid main() { undeclared = 1; }\n",
                              "bad.comp");
    FAIL() << "compiled";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("bad.comp"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("undeclared"), std::string::npos) << error.what();
  }
}

// The F0 table's texture readers (MATC_COEFFICIENTS_FROM_F0_TABLE in GLSL, the functions in HLSL)
// compile in an engine's shader: the coefficient-table device check runs their arithmetic on
// lavapipe from buffers; these are the fetches an engine calls.
TEST(SpirvApi, TheF0TableTextureReadersCompile) {
  const matc::api::Build build;
  const std::string glsl = "#version 450\n" + build.library_source("glsl") + R"(
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform sampler2D matc_f0_table;
layout(set = 0, binding = 1) uniform texture2D matc_f0_texture;
layout(set = 0, binding = 2) uniform sampler matc_nearest;
layout(std430, set = 0, binding = 3) buffer Data { vec4 values[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec3 f0 = values[i].rgb;
  MatcFresnelCoefficients in_air = MATC_COEFFICIENTS_FROM_F0_TABLE(matc_f0_table, f0);
  // A texture and a sampler bound apart, combined in the call (a comma inside the argument).
  MatcFresnelCoefficients under =
      MATC_UNDER_COAT_FROM_F0_TABLE(sampler2D(matc_f0_texture, matc_nearest), f0);
  values[i] = vec4(matc_fresnel(in_air, values[i].w) + matc_fresnel(under, values[i].w), 1.0);
}
)";
  EXPECT_FALSE(matc::api::compile_shader("glsl", glsl, "f0_table.comp").empty());
  const std::string hlsl = build.library_source("hlsl") + R"(
[[vk::binding(0, 0)]] Texture2D<float4> matc_f0_table : register(t0);
[[vk::binding(1, 0)]] RWStructuredBuffer<float4> values : register(u1);
[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  float3 f0 = values[id.x].rgb;
  MatcFresnelCoefficients in_air = matc_coefficients_from_f0_table(matc_f0_table, f0);
  MatcFresnelCoefficients under = matc_under_coat_from_f0_table(matc_f0_table, f0);
  values[id.x] = float4(matc_fresnel(in_air, values[id.x].w) + matc_fresnel(under, values[id.x].w), 1.0);
}
)";
  EXPECT_FALSE(matc::api::compile_shader("hlsl", hlsl, "f0_table.hlsl").empty());
}

// The three quick regenerations against what is checked in: the library still makes its own
// generated sources byte for byte (the fits take minutes: docs/maintainers.md reruns them).
TEST(RegenerationApi, MakesTheCheckedInSourcesAgain) {
  using matc::api::CheckedInSource;
  const auto hashes = matc::api::regenerate_source(CheckedInSource::lut_hashes);
  EXPECT_EQ(hashes.source, read_source("compiler/src/generated/default_lut_hashes.cpp"));
  EXPECT_EQ(hashes.summary.rfind("hashed ", 0), 0u) << hashes.summary;
  const auto modules = matc::api::regenerate_source(CheckedInSource::material_modules);
  EXPECT_EQ(modules.source, read_source("compiler/src/generated/material_module_templates.cpp"));
  // The default build's matc_fresnel.spv, keyed by its inputs: a stale key would only cost time
  // (every build would compile it again), so the key is held current here.
  const auto library = matc::api::regenerate_source(CheckedInSource::library_modules);
  EXPECT_EQ(library.source, read_source("compiler/src/generated/library_module_cache.cpp"));
  EXPECT_TRUE(hashes.quality_csv.empty());
}

matc::api::RegenerationOptions with_basis(const std::string& basis) {
  matc::api::RegenerationOptions options;
  options.basis = basis;
  return options;
}

matc::api::RegenerationOptions with_objective(const std::string& objective) {
  matc::api::RegenerationOptions options;
  options.ltc_objective = objective;
  return options;
}

TEST(RegenerationApi, RefusesAClosedFormBasisAndUnknownNames) {
  using matc::api::CheckedInSource;
  EXPECT_EQ(thrown_by([] {
              matc::api::regenerate_source(CheckedInSource::basis_table, with_basis("powers"));
            }),
            "basis: powers is a closed form with no table to fit");
  EXPECT_EQ(thrown_by([] {
              matc::api::regenerate_source(CheckedInSource::coefficient_table, with_basis("nope"));
            }),
            "basis: 'nope' is not one of powers, extended, paper, f82");
  EXPECT_EQ(thrown_by([] {
              matc::api::regenerate_source(CheckedInSource::ltc_table, with_objective("l2"));
            }),
            "ltc_objective: 'l2' is not one of l1, l3, polygons");
  EXPECT_EQ(matc::api::option_names("ltc_objective"),
            (std::vector<std::string>{"l1", "l3", "polygons"}));
  EXPECT_EQ(matc::api::option_default("ltc_objective"), "polygons");
}

}  // namespace
