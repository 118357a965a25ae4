// DeviceValidator: generated kernels on the Vulkan device against the CPU runtime.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "compile/compile.h"
#include "matc/api/validation.h"
#include "matc/matc.h"
#include "material/parse.h"
#include "validate/device_validator.h"

namespace {

// The talk's Figure 2 material (r = 0.44, g = [0, 1, 0]), from the examples: the build hashes the
// material's file into its shaders.
matc::CompiledMaterial figure2() {
  const matc::ParseResult parsed =
      matc::read_material_file(MATC_EXAMPLES_DIR "/figure2_edge_tint.json");
  EXPECT_TRUE(parsed.material.has_value());
  return matc::compile_material(*parsed.material, matc::runtime::shipped_basis());
}

matc::BuildOptions small_build(std::size_t embedded = 0) {
  matc::BuildOptions options;
  options.lut.size = 32;
  options.lut.samples = 256;
  options.embedded_lut_size = embedded;
  return options;
}

TEST(DeviceValidation, QueriesCoverTheTableEdgesAndBothEndsOfMu) {
  const auto queries = matc::validation_queries();
  ASSERT_EQ(queries.size(), 41u * 41u);
  EXPECT_EQ(queries.front().mu, 0.0f);
  EXPECT_EQ(queries.back().mu, 1.0f);
  EXPECT_EQ(queries.back().ndotv, 1.0f);
  EXPECT_EQ(queries.back().roughness, 1.0f);
  EXPECT_EQ(queries[40].ndotv, 1.0f);
  EXPECT_EQ(queries[40].roughness, 0.0f);
}

TEST(DeviceValidation, BothFrontEndsMatchTheCpuRuntime) {
  const matc::Build build(small_build());
  const matc::DeviceValidator validator(build, {true, ""});
  const matc::CheckResult result = validator.validate(figure2());
  ASSERT_EQ(result.paths.size(), 2u);
  EXPECT_TRUE(result.passed());
  EXPECT_EQ(result.subject, "figure2_edge_tint");
  for (const matc::PathResult& path : result.paths) {
    EXPECT_LE(path.quantity("F").max_abs, 1e-5);
    EXPECT_LE(path.quantity("Fbar").max_abs, 1e-4);
    EXPECT_LE(path.quantity("closed-form Fbar").max_abs, 1e-5);
    EXPECT_THROW(path.quantity("embedded Fbar"), std::out_of_range);  // no embedded table
  }
  EXPECT_EQ(result.paths[0].language, matc::ShaderLanguage::glsl);
  EXPECT_EQ(result.paths[1].language, matc::ShaderLanguage::hlsl);
  EXPECT_TRUE(validator.layer_messages().empty());
}

// The comparison can fail: float32 shaders are not bit-identical to the double CPU mirror, so a
// zero tolerance must reject them, and says where the worst difference was.
// --basis auto: an F82-tint material reads its own layer of the side-by-side table through its
// own functions, and a measured metal the first layer, both against the CPU runtime on the
// material's layer. Reading the wrong layer would be off by more than 0.01 (per_material_basis_
// test), a hundred times Fbar's tolerance.
TEST(DeviceValidation, APerMaterialBuildReadsEachMaterialsLayer) {
  matc::BuildOptions options = small_build();
  options.per_material_basis = true;
  const matc::Build build(options);
  const matc::DeviceValidator validator(build, {true, ""});
  for (const char* file : {"/aluminium_brushed_openpbr.json", "/figure2_edge_tint.json"}) {
    const matc::ParseResult parsed =
        matc::read_material_file(std::string(MATC_EXAMPLES_DIR) + file);
    ASSERT_TRUE(parsed.material.has_value());
    const matc::CompiledMaterial compiled =
        matc::compile_material(*parsed.material, build.basis_for(*parsed.material));
    const matc::CheckResult result = validator.validate(compiled);
    EXPECT_TRUE(result.passed()) << file;
    for (const matc::PathResult& path : result.paths) {
      EXPECT_LE(path.quantity("Fbar").max_abs, 1e-5) << file;
      EXPECT_LE(path.quantity("closed-form Fbar").max_abs, 1e-5) << file;
    }
  }
  // The shared files' checks (coefficient table, area lights) read the first layer through
  // matc_lut_texcoord over the wider table.
  for (const auto& check : validator.shared_file_checks())
    EXPECT_TRUE(validator.run(*check).passed()) << check->subject();
  EXPECT_TRUE(validator.layer_messages().empty());
}

TEST(DeviceValidation, ZeroToleranceFails) {
  const matc::Build build(small_build(4));
  const matc::DeviceValidator validator(build, {false, ""}, {0.0, 0.0, 0.0});
  const matc::CheckResult result = validator.validate(figure2());
  EXPECT_FALSE(result.passed());
  const auto check = matc::material_check(build, figure2(), validator.tolerance());
  for (const matc::PathResult& path : result.paths) {
    EXPECT_FALSE(path.passed());
    const matc::CheckedQuantity& fresnel = path.quantity("F");
    EXPECT_GT(fresnel.max_abs, 0.0);
    EXPECT_LT(fresnel.max_abs, 1e-5);
    EXPECT_LT(path.quantity("embedded Fbar").max_abs, 1e-5);
    // A report can say where the worst difference was.
    EXPECT_NE(check->describe_query(fresnel.worst_query, "F").find("mu "), std::string::npos);
  }
}

}  // namespace

// The coefficient-table path (textured metals) from both front ends, with the validation layer
// on, for every shipped basis and an f16 table.
TEST(DeviceValidation, CoefficientTablePathMatchesTheCpuRuntime) {
  for (const auto basis : matc::runtime::kShippedBases) {
    for (const auto precision : {matc::LutPrecision::f32, matc::LutPrecision::f16}) {
      matc::BuildOptions options = small_build();
      options.per_material_basis = false;
      options.basis = basis;
      options.coefficient_table_precision = precision;
      const matc::Build build(options);
      const matc::DeviceValidator validator(build, {true, ""});
      const matc::CheckResult result =
          validator.run(*matc::coefficient_table_check(build, validator.tolerance()));
      ASSERT_EQ(result.paths.size(), 2u);
      EXPECT_TRUE(result.passed()) << matc::runtime::basis_name(basis);
      for (const matc::PathResult& path : result.paths) {
        ASSERT_EQ(path.quantities.size(), 8u);
        for (const char* label : {"F(r, g)", "Fbar(r, g)", "F(n, k)", "F(baked)", "F(from F0)",
                                  "F(F0 table)", "F(F0 table, under a coat)", "F(metal-rough)"})
          EXPECT_LE(path.quantity(label).max_abs, 1e-4) << label;
      }
      EXPECT_TRUE(validator.layer_messages().empty());
    }
  }
}

TEST(DeviceValidation, CoefficientTableQueriesReachTheTableEdges) {
  const auto queries = matc::table_validation_queries();
  ASSERT_EQ(queries.size(), 4096u);
  bool r0 = false, r1 = false, g0 = false, g1 = false;
  for (const matc::TableQuery& q : queries) {
    for (std::size_t c = 0; c < 3; ++c) {
      r0 |= q.reflectivity[c] == 0.0f;
      r1 |= q.reflectivity[c] == 1.0f;
      g0 |= q.edge_tint[c] == 0.0f;
      g1 |= q.edge_tint[c] == 1.0f;
      EXPECT_GE(q.n[c], 0.05f);
      EXPECT_LE(q.k[c], 8.0f);
    }
  }
  EXPECT_TRUE(r0 && r1 && g0 && g1);
}

// A zero tolerance fails the table path too: the check can fail.
TEST(DeviceValidation, CoefficientTableZeroToleranceFails) {
  const matc::Build build(small_build());
  const matc::DeviceValidator validator(build, {false, ""}, {0.0, 0.0, 0.0});
  EXPECT_FALSE(validator.run(*matc::coefficient_table_check(build, {0.0, 0.0, 0.0})).passed());
}

// The area-light functions (LTC quad and disk lights) from both front ends, with the validation
// layer on, against the CPU runtime.
TEST(DeviceValidation, AreaLightsMatchTheCpuRuntime) {
  const matc::Build build(small_build());
  const matc::DeviceValidator validator(build, {true, ""});
  const matc::CheckResult result =
      validator.run(*matc::area_light_check(build, validator.tolerance()));
  ASSERT_EQ(result.paths.size(), 2u);
  for (const matc::PathResult& path : result.paths) {
    EXPECT_LE(path.quantity("L").max_abs, 1e-4);
    EXPECT_LE(path.quantity("I_ltc").max_abs, 1e-4);
  }
  EXPECT_TRUE(result.passed());
  EXPECT_TRUE(validator.layer_messages().empty());
}

TEST(DeviceValidation, AreaLightQueriesCoverQuadsDisksSpheresAndTheHorizon) {
  const auto queries = matc::area_light_validation_queries();
  ASSERT_EQ(queries.size(), 2048u);
  std::size_t disks = 0, spheres = 0, crossing = 0;
  for (const matc::AreaLightQuery& q : queries) {
    disks += q.kind == matc::AreaLightQuery::Kind::disk ? 1 : 0;
    spheres += q.kind == matc::AreaLightQuery::Kind::sphere ? 1 : 0;
    if (q.kind == matc::AreaLightQuery::Kind::sphere) {
      const auto& c = q.points[0];
      EXPECT_LT(q.radius, std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
    }
    if (q.kind != matc::AreaLightQuery::Kind::quad) continue;
    // A corner below the shading point's horizon: N . p < 0.
    bool below = false, above = false;
    for (const auto& p : q.points) {
      const float height = p[0] * q.normal[0] + p[1] * q.normal[1] + p[2] * q.normal[2];
      below |= height < 0.0f;
      above |= height > 0.0f;
    }
    crossing += below && above ? 1 : 0;
  }
  EXPECT_EQ(disks, 256u);
  EXPECT_EQ(spheres, 256u);
  EXPECT_GT(crossing, 100u);
}

// A zero tolerance fails the area-light path: the check can fail.
TEST(DeviceValidation, AreaLightZeroToleranceFails) {
  const matc::Build build(small_build());
  const matc::DeviceValidator validator(build, {false, ""}, {0.0, 0.0, 0.0});
  EXPECT_FALSE(validator.run(*matc::area_light_check(build, {0.0, 0.0, 0.0})).passed());
}

// The shared files' checks follow --emit: the coefficient-table path with the coefficient table,
// the area lights with the LTC table.
TEST(DeviceValidation, SharedFileChecksFollowTheOutputs) {
  matc::BuildOptions options = small_build();
  const auto subjects = [](const matc::Build& build) {
    std::vector<std::string> names;
    for (const auto& check : matc::shared_file_checks(build, {}))
      names.push_back(check->subject());
    return names;
  };
  EXPECT_EQ(subjects(matc::Build(options)),
            (std::vector<std::string>{"coefficient table", "area lights (LTC)"}));
  options.emit = {matc::OutputKind::glsl, matc::OutputKind::ltc};
  EXPECT_EQ(subjects(matc::Build(options)), (std::vector<std::string>{"area lights (LTC)"}));
  options.emit = {matc::OutputKind::glsl};
  EXPECT_TRUE(subjects(matc::Build(options)).empty());
}

namespace {

// The public face (matc/api/validation.h) gives the same checks, their results as plain values.
TEST(PublicDeviceValidation, TheLibrarysChecksAsPublicResults) {
  matc::api::BuildOptions options;
  options.lut_size = 32;
  options.lut_samples = 256;
  const matc::api::Build build(options);
  const matc::api::DeviceValidation validation(build, {true, ""});
  const matc::api::Material material =
      matc::api::load_materials(MATC_EXAMPLES_DIR "/figure2_edge_tint.json").at(0);
  const matc::api::CheckResult result = validation.check(build.compile(material));
  EXPECT_EQ(result.subject, "figure2_edge_tint");
  ASSERT_EQ(result.front_ends.size(), 2u);
  EXPECT_EQ(result.front_ends[0].language, "GLSL");
  EXPECT_EQ(result.front_ends[1].language, "HLSL");
  for (const matc::api::FrontEndResult& front_end : result.front_ends) {
    ASSERT_FALSE(front_end.quantities.empty());
    EXPECT_EQ(front_end.quantities[0].label, "F");
    EXPECT_LE(front_end.quantities[0].max_abs, validation.fresnel_tolerance());
  }
  EXPECT_TRUE(result.passed());
  EXPECT_TRUE(result.layer_messages.empty());
  EXPECT_FALSE(validation.check_shared_files().empty());
  // A material compiled with other options than the build's is refused.
  EXPECT_THROW(validation.check(matc::api::compile(material, {"paper", "", ""})),
               std::invalid_argument);
}

}  // namespace

// A coated metal's kernel checks both lobes and glTF's metal-rough mix under its coat
// (matc_metal_rough_<name>, the dielectric times the coat's transmission) against the runtime.
TEST(DeviceValidation, CoatedMetalRoughMixMatchesTheCpuRuntime) {
  const matc::ParseResult parsed =
      matc::read_material_file(MATC_EXAMPLES_DIR "/copper_lacquered.json");
  ASSERT_TRUE(parsed.material.has_value());
  const matc::Build build(small_build());
  const matc::DeviceValidator validator(build, {true, ""});
  const matc::CheckResult result =
      validator.validate(matc::compile_material(*parsed.material, matc::runtime::shipped_basis()));
  ASSERT_EQ(result.paths.size(), 2u);
  EXPECT_TRUE(result.passed());
  for (const matc::PathResult& path : result.paths) {
    EXPECT_LE(path.quantity("F(metal-rough)").max_abs, 1e-5);
    EXPECT_LE(path.quantity("coat transmission").max_abs, 1e-5);
    EXPECT_GT(path.quantity("coat transmission").max_abs, 0.0);  // float32 against double
  }
}
