// The quality level of area lights: the vector form factor, where a light lies on the LTC's
// lobe, and the Fresnel that follows it (runtime/ltc.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "compile/compile.h"
#include "emit/build.h"
#include "ltc/area_light_reference.h"
#include "ltc/ggx_lobe.h"
#include "ltc/lobe_polygons.h"
#include "ltc/polygon_light.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/ltc_following.h"
#include "material/parse.h"

namespace {

using matc::Vec3;
using matc::runtime::dot;
using matc::runtime::normalize;

const matc::Build& default_build() {
  static const matc::Build build(matc::one_basis_build());
  return build;
}

matc::CompiledMaterial example(const char* name) {
  const matc::ParseResult parsed =
      matc::read_material_file(std::string(MATC_EXAMPLES_DIR) + "/" + name + ".json");
  return matc::compile_material(*parsed.material, default_build().basis());
}

// A small square light at distance 3 along `direction`, facing the point.
std::array<Vec3, 4> small_light(const Vec3& direction) {
  return matc::facing_square(direction, 3.0, 0.003);
}

TEST(LtcFollowing, VectorFormFactorPointsAtTheLightAndKeepsTheFormFactor) {
  for (const Vec3& towards : {Vec3{0, 0, 1}, Vec3{0.6, -0.3, 0.5}, Vec3{-1, 0.2, 0.1}}) {
    const auto light = small_light(towards);
    const Vec3 f = matc::runtime::clipped_polygon_vector_form_factor(light);
    EXPECT_EQ(f[2], matc::runtime::clipped_polygon_form_factor(light));
    EXPECT_GT(dot(normalize(f), normalize(towards)), 1.0 - 1e-6);
    // Either winding.
    const std::array<Vec3, 4> reversed = {light[3], light[2], light[1], light[0]};
    const Vec3 r = matc::runtime::clipped_polygon_vector_form_factor(reversed);
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(r[k], f[k], 1e-15);
  }
  // A wall half below the horizon: the clipped part's vector leans up, away from the cut.
  const std::vector<Vec3> wall = {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}};
  const Vec3 f = matc::runtime::clipped_polygon_vector_form_factor(wall);
  EXPECT_GT(f[2], 0.0);
  EXPECT_GT(f[0], f[2]);
  EXPECT_NEAR(f[1], 0.0, 1e-12);
}

// The direction is taken back through M by its adjugate, which needs ad - bc > 0.
TEST(LtcFollowing, ShippedTexelsHavePositiveDeterminants) {
  const matc::runtime::LtcTableView table = matc::runtime::shipped_ltc_table();
  for (std::size_t y = 0; y < table.size; ++y) {
    for (std::size_t x = 0; x < table.size; ++x) {
      const auto t = table.texel(x, y);
      ASSERT_GT((matc::runtime::LtcInverse{t[0], t[1], t[2], t[3]}.determinant()), 0.0)
          << "texel " << x << ", " << y;
    }
  }
}

TEST(LtcFollowing, LitDirectionOfASmallLightIsTheLightsDirection) {
  const matc::runtime::LtcTableView table = matc::runtime::shipped_ltc_table();
  for (const double ndotv : {0.2, 0.7, 1.0}) {
    for (const double roughness : {0.2, 0.5, 0.9}) {
      for (const Vec3& towards : {Vec3{-0.5, 0.0, 0.8}, Vec3{0.3, 0.6, 0.4}}) {
        const auto lit = matc::runtime::ltc_lit_polygon(
            matc::runtime::sample_ltc(table, ndotv, roughness), small_light(towards));
        EXPECT_GT(lit.integral, 0.0);
        EXPECT_GT(dot(lit.direction, normalize(towards)), 1.0 - 1e-5)
            << "NdotV " << ndotv << ", roughness " << roughness;
      }
    }
  }
}

// The runtime's GGX lobe (what the shaders evaluate) is the fit's and the reference's.
TEST(LtcFollowing, LobeMatchesTheReferenceLobe) {
  for (const double ndotv : {0.05, 0.4, 0.9}) {
    for (const double roughness : {0.1, 0.5, 1.0}) {
      const matc::GgxLobe lobe(ndotv, roughness);
      for (const Vec3& l : {Vec3{0, 0, 1}, normalize({-0.7, 0.1, 0.4}), normalize({0.3, -0.8, 0.2}),
                            normalize({0.5, 0.0, -0.1})}) {
        const double expected = lobe.evaluate(l).lobe;
        EXPECT_NEAR(matc::runtime::ggx_lobe_cosine(ndotv, roughness, l), expected,
                    1e-12 * std::max(1.0, expected));
      }
    }
  }
}

// A small light sees the lobe's own density and the Fresnel at its half vector, as a punctual
// light would: L = f cos F(V.H) times its solid angle. A light over the whole hemisphere sees the
// LTC's integral and the lobe's average, as the one-shape path.
TEST(LtcFollowing, SmallLightSeesTheLobeWhereItLiesAndTheSkyTheLobesAverage) {
  const matc::CompiledMaterial material = example("figure2_edge_tint");
  const matc::runtime::LutView lut = default_build().stored_lut().view();
  const matc::runtime::LtcTableView ltc = matc::runtime::shipped_ltc_table();
  const auto& basis = matc::runtime::shipped_shader_basis();
  const double ndotv = 0.3, roughness = 0.6;
  const Vec3 view{std::sqrt(1.0 - ndotv * ndotv), 0.0, ndotv};
  const Vec3 towards = normalize({-0.2, 0.4, 0.9});
  const auto light = small_light(towards);
  const double solid_angle = (2.0 * 0.003) * (2.0 * 0.003) / (3.0 * 3.0);
  const double vdoth = dot(view, normalize(matc::runtime::plus(view, towards)));
  const matc::Rgb f = matc::runtime::evaluate_fresnel(material.coefficients, basis, vdoth);
  const double lobe = matc::runtime::ggx_lobe_cosine(ndotv, roughness, towards);
  const matc::Rgb small = matc::runtime::polygon_light_ltc_following(
      material.coefficients, lut, basis, ltc, ndotv, roughness, light);
  const matc::Rgb one_shape =
      matc::runtime::polygon_light_ltc(material.coefficients, lut, ltc, ndotv, roughness, light);
  for (std::size_t c = 0; c < 3; ++c) {
    const double punctual = lobe * solid_angle * f[c];
    EXPECT_NEAR(small[c], punctual, 5e-3 * punctual) << "channel " << c;
    // The one shape's error there is well above that: the test means something.
    EXPECT_GT(std::abs(one_shape[c] - punctual), 0.05 * punctual) << "channel " << c;
  }
  const std::vector<Vec3> sky = {{-1e4, -1e4, 1}, {1e4, -1e4, 1}, {1e4, 1e4, 1}, {-1e4, 1e4, 1}};
  const matc::Rgb following = matc::runtime::polygon_light_ltc_following(
      material.coefficients, lut, basis, ltc, ndotv, roughness, sky);
  const matc::Rgb sky_one_shape =
      matc::runtime::polygon_light_ltc(material.coefficients, lut, ltc, ndotv, roughness, sky);
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_NEAR(following[c], sky_one_shape[c], 1e-3 * sky_one_shape[c]);
}

// Against the exact integral over random quads (lobe_polygons.h) at several views: the quality
// level is closer than one shape, by most in the edge-tinted channel (radiance-weighted).
TEST(LtcFollowing, CloserToTheExactIntegralThanOneShape) {
  const matc::CompiledMaterial material = example("figure2_edge_tint");
  const auto curve = matc::make_reflectance_curve(material.material, material.color);
  const matc::TabulatedCurve exact(*curve);
  const matc::runtime::LutView lut = default_build().stored_lut().view();
  const matc::runtime::LtcTableView ltc = matc::runtime::shipped_ltc_table();
  const auto& basis = matc::runtime::shipped_shader_basis();
  matc::Rgb one_shape_error{}, following_error{};
  for (const double ndotv : {0.15, 0.4, 0.7}) {
    for (const double roughness : {0.3, 0.55, 0.8}) {
      const matc::GgxLobe lobe(ndotv, roughness);
      for (const matc::LobePolygon& quad :
           matc::lobe_polygons(lobe, 1.0, matc::lobe_polygon_seed(5, ndotv, roughness), 8, 1)) {
        const matc::Rgb reference =
            matc::integrate_polygon_light(
                lobe, quad.vertices, [&](double mu) { return exact.at(mu); }, 1 << 13)
                .mean;
        const matc::Rgb one_shape = matc::runtime::polygon_light_ltc(
            material.coefficients, lut, ltc, ndotv, roughness, quad.vertices);
        const matc::Rgb following = matc::runtime::polygon_light_ltc_following(
            material.coefficients, lut, basis, ltc, ndotv, roughness, quad.vertices);
        for (std::size_t c = 0; c < 3; ++c) {
          one_shape_error[c] += std::abs(one_shape[c] - reference[c]);
          following_error[c] += std::abs(following[c] - reference[c]);
        }
      }
    }
  }
  EXPECT_LT(following_error[1], 0.7 * one_shape_error[1]);
  EXPECT_LT(following_error[0], one_shape_error[0]);
  EXPECT_LT(following_error[2], one_shape_error[2]);
}

}  // namespace
