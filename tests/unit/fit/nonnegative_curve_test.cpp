// Materials whose curve matc proves non-negative get shader functions without the clamp at 0
// (fit/nonnegative_curve.h). The proof is checked against what a shader actually reads: F at
// many cosines, every texel of the preintegrated table as a file stores it (f16 and f32), and the
// table's closed form; the clamp stays for near-black metals and the fitted bases.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "compile/compile.h"
#include "emit/build.h"
#include "example_files.h"
#include "fit/nonnegative_curve.h"
#include "lut/lut_files.h"
#include "lut/preintegrate.h"
#include "matc/runtime/analytic_lut.h"
#include "matc/runtime/shader_basis.h"
#include "material/parse.h"

namespace {

using matc::CompiledMaterial;

std::vector<CompiledMaterial> compile_examples(matc::runtime::BasisKind kind) {
  std::vector<CompiledMaterial> compiled;
  for (const std::string& file : matc::test::example_material_files()) {
    matc::ParseResult parsed = matc::read_material_file(file);
    if (!parsed.material) throw std::runtime_error("example does not parse: " + file);
    compiled.push_back(
        matc::compile_material(*parsed.material, matc::runtime::shipped_basis(kind)));
  }
  return compiled;
}

CompiledMaterial compile_text(const std::string& json) {
  const matc::ParseResult parsed = matc::parse_material(json, "test.json");
  if (!parsed.material) throw std::runtime_error("test material does not parse");
  return matc::compile_material(*parsed.material, matc::runtime::shipped_basis());
}

// sum_i c_i v_i per channel, unclamped: what the shaders' _sum functions compute.
std::array<double, 3> unclamped(const matc::runtime::Coefficients& c,
                                const std::array<double, 4>& v) {
  std::array<double, 3> sums{};
  for (std::size_t channel = 0; channel < 3; ++channel)
    for (std::size_t i = 0; i < 4; ++i)
      sums[channel] += c[channel][i] * v[i];
  return sums;
}

TEST(NonnegativeCurve, ProvenCurvesStayAboveZeroWhereverAShaderReadsThem) {
  const auto materials = compile_examples(matc::runtime::kDefaultBasis);
  const auto& shader_basis = matc::runtime::shipped_shader_basis();
  const matc::Lut lut = matc::preintegrate_lut(matc::runtime::shipped_basis(), matc::LutOptions{});
  const std::array<matc::Lut, 2> stored = {matc::stored_as(lut, matc::LutPrecision::f16),
                                           matc::stored_as(lut, matc::LutPrecision::f32)};
  const auto& analytic = matc::runtime::shipped_analytic_lut(matc::runtime::kDefaultBasis);
  std::size_t proven = 0;
  for (const CompiledMaterial& material : materials) {
    if (!material.fresnel_nonnegative) continue;
    ++proven;
    const std::string& name = material.material.name;
    for (int k = 0; k <= 100000; ++k) {
      const double mu = k / 100000.0;
      for (const double f :
           unclamped(material.coefficients, matc::runtime::evaluate_shader_basis(shader_basis, mu)))
        ASSERT_GE(f, 0.0) << name << " F at mu " << mu;
    }
    for (const matc::Lut& table : stored) {
      const auto view = table.view();
      for (std::size_t y = 0; y < table.size; ++y) {
        for (std::size_t x = 0; x < table.size; ++x) {
          const auto texel = view.texel(x, y);
          const std::array<double, 4> bbar = {texel[0], texel[1], texel[2], texel[3]};
          for (const double f : unclamped(material.coefficients, bbar))
            ASSERT_GE(f, 0.0) << name << " Fbar at texel " << x << ", " << y;
        }
      }
    }
    for (int j = 0; j <= 64; ++j) {
      for (int i = 0; i <= 64; ++i) {
        const auto bbar = matc::runtime::preintegrated_basis_analytic(analytic, i / 64.0, j / 64.0);
        for (const double f : unclamped(material.coefficients, bbar))
          ASSERT_GE(f, 0.0) << name << " closed-form Fbar at " << i << ", " << j;
      }
    }
  }
  // The point of it: most metals need no clamp.
  EXPECT_GE(proven, materials.size() * 3 / 4) << proven << " of " << materials.size();
}

TEST(NonnegativeCurve, NearBlackMetalsAndFittedBasesKeepTheClamp) {
  const CompiledMaterial near_black = compile_text(
      R"({"name": "soot", "artistic": {"reflectivity": [1e-6, 1e-6, 1e-6], "edge_tint": [0.5, 0.5, 0.5]}})");
  EXPECT_FALSE(near_black.fresnel_nonnegative);
  const CompiledMaterial bright = compile_text(
      R"({"name": "steel", "artistic": {"reflectivity": [0.56, 0.57, 0.58], "edge_tint": [0.6, 0.6, 0.6]}})");
  EXPECT_TRUE(bright.fresnel_nonnegative);
  for (const CompiledMaterial& material : compile_examples(matc::runtime::BasisKind::extended))
    EXPECT_FALSE(material.fresnel_nonnegative) << material.material.name;

  // What the shaders get: the unclamped functions only for the proven curve.
  const matc::Build build(matc::BuildOptions{});
  const std::string proven = build.material_source(matc::ShaderLanguage::glsl, bright);
  const std::string clamped = build.material_source(matc::ShaderLanguage::glsl, near_black);
  EXPECT_NE(proven.find("return matc_fresnel_sum(matc_coefficients_steel, mu);"),
            std::string::npos);
  EXPECT_NE(proven.find("return matc_fresnel_preintegrated_sum(matc_coefficients_steel, bbar);"),
            std::string::npos);
  EXPECT_NE(clamped.find("return matc_fresnel(matc_coefficients_soot, mu);"), std::string::npos);
  EXPECT_NE(clamped.find("return matc_fresnel_preintegrated(matc_coefficients_soot, bbar);"),
            std::string::npos);
}

// The closed form's quadrature blends two values of F with a weight the shader clamps to [0, 1],
// times the albedo: the fit keeps the albedo well above 0 over the whole domain.
TEST(NonnegativeCurve, ClosedFormAlbedoStaysPositive) {
  for (const auto kind : matc::runtime::kShippedBases) {
    const auto& analytic = matc::runtime::shipped_analytic_lut(kind);
    double lowest = 1.0;
    for (int j = 0; j <= 256; ++j)
      for (int i = 0; i <= 256; ++i)
        lowest = std::min(
            lowest, matc::runtime::analytic_lut_fields(analytic, i / 256.0, j / 256.0).albedo);
    EXPECT_GT(lowest, 0.25) << matc::runtime::basis_name(kind);
  }
}

}  // namespace
