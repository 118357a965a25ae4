// Area lights with linearly transformed cosines: the checked-in LTC table, the polygon integral
// against independent quadrature, the fit against the GGX lobe, the reference integrator, and the
// checks on the lights the tools take.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "ltc/area_light_reference.h"
#include "ltc/ggx_lobe.h"
#include "ltc/lobe_polygons.h"
#include "ltc/ltc_fit.h"
#include "ltc/polygon_light.h"
#include "lut/preintegrate.h"
#include "matc/runtime/ltc.h"

namespace {

using matc::Vec3;

const matc::FresnelAtCosine kOne = [](double) { return matc::runtime::Rgb{1.0, 1.0, 1.0}; };

// The cosine's integral over a planar quad by the midpoint rule on its area: independent of the
// edge formula (cos(theta_L) cos(theta_light) / r^2 dA / pi), clipped by dropping z <= 0.
double quadrature_form_factor(const std::vector<Vec3>& quad, int steps) {
  const auto lerp = [](const Vec3& a, const Vec3& b, double t) {
    return Vec3{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
  };
  const Vec3 e1{quad[1][0] - quad[0][0], quad[1][1] - quad[0][1], quad[1][2] - quad[0][2]};
  const Vec3 e2{quad[3][0] - quad[0][0], quad[3][1] - quad[0][1], quad[3][2] - quad[0][2]};
  const Vec3 n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
               e1[0] * e2[1] - e1[1] * e2[0]};  // |n| = area of the parallelogram
  double sum = 0.0;
  for (int j = 0; j < steps; ++j) {
    for (int i = 0; i < steps; ++i) {
      const double u = (i + 0.5) / steps, v = (j + 0.5) / steps;
      const Vec3 p = lerp(lerp(quad[0], quad[1], u), lerp(quad[3], quad[2], u), v);
      if (p[2] <= 0.0) continue;
      const double r2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
      const double r = std::sqrt(r2);
      const double cos_light = std::abs(n[0] * p[0] + n[1] * p[1] + n[2] * p[2]) / r;
      sum += (p[2] / r) * cos_light / r2;
    }
  }
  return sum / (steps * steps) / std::numbers::pi;
}

// The checked-in table is what `matc basis ltc-table` fits today, bit for bit (rows are fitted
// independently, so two of them stand for the whole table here).
TEST(LtcTable, CheckedInTableIsCurrent) {
  const matc::runtime::LtcTableView shipped = matc::runtime::shipped_ltc_table();
  ASSERT_EQ(shipped.size, matc::kDefaultLtcSize);
  for (const std::size_t row : {std::size_t{3}, std::size_t{40}}) {
    const matc::LtcTable fitted = matc::fit_ltc_table({.size = shipped.size}, row, 1);
    for (std::size_t x = 0; x < shipped.size; ++x) {
      const auto expected = shipped.texel(x, row);
      for (std::size_t c = 0; c < 4; ++c)
        ASSERT_EQ(fitted.view().texel(x, row)[c], expected[c]) << "texel " << x << ", " << row;
    }
  }
}

TEST(LtcIntegral, ClippedFormFactorMatchesQuadrature) {
  const std::vector<std::vector<Vec3>> quads = {
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},                    // overhead
      {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},                    // a wall, half below
      {{-2, -0.5, 0.2}, {-1, -0.5, 1.5}, {-1, 0.5, 1.5}, {-2, 0.5, 0.2}},  // tilted
      {{0.5, -3, -0.5}, {0.5, 3, -0.5}, {0.5, 3, 0.1}, {0.5, -3, 0.1}},    // mostly below
  };
  for (const auto& quad : quads) {
    const double quadrature = quadrature_form_factor(quad, 1500);
    EXPECT_NEAR(matc::runtime::clipped_polygon_form_factor(quad), quadrature, 2e-4);
    // Either winding: a two-sided light.
    const std::vector<Vec3> reversed(quad.rbegin(), quad.rend());
    EXPECT_NEAR(matc::runtime::clipped_polygon_form_factor(reversed),
                matc::runtime::clipped_polygon_form_factor(quad), 1e-12);
  }
  // Entirely below the horizon: nothing.
  EXPECT_EQ(matc::runtime::clipped_polygon_form_factor(
                std::vector<Vec3>{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}}),
            0.0);
}

TEST(LtcIntegral, DiskPolygonHasTheDisksFormFactor) {
  // A disk of radius R facing the point at height h on the normal: R^2 / (R^2 + h^2).
  for (const double radius : {0.2, 1.0, 3.0}) {
    const auto disk = matc::runtime::disk_light_polygon({0, 0, 1}, {0, 0, -1}, radius);
    EXPECT_NEAR(matc::runtime::clipped_polygon_form_factor(disk),
                radius * radius / (radius * radius + 1.0),
                2e-3 * radius * radius / (radius * radius + 1.0));
  }
}

TEST(LtcIntegral, SphereLightFillsTheSpheresCone) {
  // A sphere of radius R at distance 1 on the normal: the cone's form factor is R^2.
  for (const double radius : {0.1, 0.5, 0.9}) {
    const auto disk = matc::runtime::sphere_light_polygon({0, 0, 0}, {0, 0, 1}, radius);
    EXPECT_NEAR(matc::runtime::clipped_polygon_form_factor(disk), radius * radius,
                2e-3 * radius * radius);
  }
}

// The LTC times the albedo against the GGX lobe's own integral over a light (F = 1), where the
// fit is good (the per-texel quality is docs/ltc.md's).
TEST(LtcFit, QuadLightIntegralFollowsTheLobe) {
  const std::vector<Vec3> quad = {
      {-1.5, -0.5, 0.8}, {-0.5, -0.5, 1.8}, {-0.5, 0.5, 1.8}, {-1.5, 0.5, 0.8}};
  for (const double ndotv : {0.9, 0.5}) {
    for (const double roughness : {0.25, 0.5, 0.8}) {
      const matc::GgxLobe lobe(ndotv, roughness);
      const double albedo = lobe.albedo(64);
      const auto reference = matc::integrate_polygon_light(lobe, quad, kOne, 1 << 16);
      const double ltc = matc::runtime::ltc_polygon_integral(
          matc::runtime::sample_ltc(matc::runtime::shipped_ltc_table(), ndotv, roughness), quad);
      EXPECT_NEAR(albedo * ltc, reference.mean[0], 0.03 * albedo)
          << "NdotV " << ndotv << ", roughness " << roughness;
    }
  }
}

// The view axis is nearly linear in the view angle, so that a smooth lobe's direction
// interpolates between columns: a small light at the mirror direction of a view between two
// columns gets its share. On the preintegrated table's sqrt(NdotV) axis the last two columns
// (NdotV 0.97 and 1) placed the lobe up to 3 degrees off and this light got nothing.
TEST(LtcTable, ASmoothLobeFollowsTheMirrorBetweenColumns) {
  using matc::runtime::LtcViewAxis;
  for (const auto axis : {LtcViewAxis::angular, LtcViewAxis::sqrt_ndotv}) {
    for (const double u : {0.0, 0.3, 1.0}) {
      EXPECT_NEAR(matc::runtime::ltc_u_from_ndotv(matc::runtime::ltc_ndotv_from_u(u, axis), axis),
                  u, 1e-12);
    }
  }
  EXPECT_NEAR(matc::runtime::ltc_u_from_ndotv(0.75), 0.5, 1e-12);
  const matc::runtime::LtcTableView table = matc::runtime::shipped_ltc_table();
  constexpr double kRoughness = 0.1;
  for (std::size_t x = 0; x + 1 < table.size; ++x) {
    const double u = (static_cast<double>(x) + 0.5) / static_cast<double>(table.size - 1);
    const double ndotv = matc::runtime::ltc_ndotv_from_u(u);
    if (ndotv < 0.1) continue;
    const double sine = std::sqrt(1.0 - ndotv * ndotv);
    const auto square = matc::facing_square({-sine, 0.0, ndotv}, 1.0, 0.04);
    const matc::GgxLobe lobe(ndotv, kRoughness);
    const double share =
        matc::integrate_polygon_light(lobe, square, kOne, 1 << 14).mean[0] / lobe.albedo(64);
    const double ltc = matc::runtime::ltc_polygon_integral(
        matc::runtime::sample_ltc(table, ndotv, kRoughness), square);
    EXPECT_GT(share, 0.5) << "NdotV " << ndotv;
    EXPECT_NEAR(ltc, share, 0.1) << "NdotV " << ndotv;
  }
}

// The closed form of the mass below the horizon against the LTC's integral over a quad that
// covers nearly all of the upper hemisphere.
TEST(LtcFit, MassBelowTheHorizonIsWhatTheSkyMisses) {
  const std::vector<Vec3> sky = {
      {-1e4, -1e4, 1e-3}, {1e4, -1e4, 1e-3}, {1e4, 1e4, 1e-3}, {-1e4, 1e4, 1e-3}};
  const matc::runtime::LtcTableView table = matc::runtime::shipped_ltc_table();
  for (const double ndotv : {0.05, 0.4, 1.0}) {
    for (const double roughness : {0.2, 0.6, 0.9}) {
      const matc::runtime::LtcInverse inverse = matc::runtime::sample_ltc(table, ndotv, roughness);
      EXPECT_NEAR(1.0 - matc::ltc_mass_below_horizon(inverse),
                  matc::runtime::ltc_polygon_integral(inverse, sky), 1e-5)
          << "NdotV " << ndotv << ", roughness " << roughness;
    }
  }
  EXPECT_NEAR(matc::ltc_mass_below_horizon({1.0, 0.0, 0.0, 1.0}), 0.0, 1e-12);
  EXPECT_NEAR(matc::ltc_mass_below_horizon({0.0, -1.0, 1.0, 0.0}), 0.5, 1e-12);
}

TEST(LtcFit, NormalIncidenceIsIsotropicAndTheRowsAreIndependent) {
  const matc::runtime::LtcTableView table = matc::runtime::shipped_ltc_table();
  for (std::size_t y = 1; y < table.size; ++y) {
    const auto texel = table.texel(table.size - 1, y);  // NdotV = 1
    EXPECT_NEAR(texel[1], 0.0f, 1e-6f);                 // b
    EXPECT_NEAR(texel[2], 0.0f, 1e-6f);                 // c
    EXPECT_NEAR(texel[0], 1.0f, 1e-5f);                 // a = m22 / m11 = 1
  }
  // The same row fitted on one thread and on several.
  const matc::LtcTable one = matc::fit_ltc_table({.size = 16, .threads = 1}, 5, 3);
  const matc::LtcTable many = matc::fit_ltc_table({.size = 16, .threads = 3}, 5, 3);
  EXPECT_EQ(one.texels, many.texels);
  EXPECT_THROW(matc::fit_ltc_table({.size = 1}), std::invalid_argument);
}

TEST(LtcFit, EvaluatingAStoredTexelGivesTheFitsDistances) {
  const matc::LtcCellFit fit = matc::fit_ltc_cell(0.4, 0.5, {0.25, 0.25, 0.0, -1.1}, false);
  const matc::LtcCellFit again = matc::evaluate_ltc_cell(fit.inverse, 0.4, 0.5);
  EXPECT_NEAR(again.l1_distance, fit.l1_distance, 1e-9);
  EXPECT_NEAR(again.cubed_distance, fit.cubed_distance, 1e-9 * fit.cubed_distance);
  EXPECT_NEAR(again.shape.angle, fit.shape.angle, 1e-9);
  EXPECT_LT(fit.l1_distance, 0.25);
}

// The floor docs/ltc.md measures: fitted to a set of quads, the LTC beats the shipped texel on
// them, each aggregate (mean, largest) on its own terms.
TEST(LtcFit, FittingToTheQuadsThemselvesBeatsTheTableOnThem) {
  const double ndotv = 0.4, roughness = 0.5;
  const matc::GgxLobe lobe(ndotv, roughness);
  const std::vector<matc::LobePolygon> quads =
      matc::lobe_polygons(lobe, lobe.albedo(matc::kLtcFitSamplesPerAxis),
                          matc::lobe_polygon_seed(7, ndotv, roughness), 16, 2048);
  const matc::runtime::LtcInverse shipped =
      matc::runtime::sample_ltc(matc::runtime::shipped_ltc_table(), ndotv, roughness);
  const matc::PolygonSetError before = matc::ltc_polygon_set_error(shipped, quads);
  const matc::PolygonSetError mean_fit = matc::ltc_polygon_set_error(
      matc::fit_ltc_to_polygons(shipped, ndotv, roughness, quads, matc::PolygonSetAggregate::mean)
          .inverse,
      quads);
  const matc::PolygonSetError max_fit = matc::ltc_polygon_set_error(
      matc::fit_ltc_to_polygons(shipped, ndotv, roughness, quads, matc::PolygonSetAggregate::max)
          .inverse,
      quads);
  EXPECT_LT(mean_fit.mean, 0.95 * before.mean);
  EXPECT_LT(max_fit.max, 0.95 * before.max);
  EXPECT_LE(mean_fit.mean, max_fit.mean);
  EXPECT_LE(max_fit.max, mean_fit.max);
}

TEST(GgxLobe, AlbedoMatchesThePreintegratedTable) {
  const matc::runtime::BasisView basis = matc::runtime::shipped_basis();
  for (const double ndotv : {0.1, 0.5, 1.0}) {
    for (const double roughness : {0.2, 0.6, 1.0}) {
      const double table = matc::preintegrate_basis(basis, ndotv, roughness, 1 << 14)[0];
      EXPECT_NEAR(matc::GgxLobe(ndotv, roughness).albedo(128), table, 2e-3);
    }
  }
}

TEST(AreaLightReference, HemisphereLightGivesTheAlbedoAndErrorsShrink) {
  const std::vector<Vec3> sky = {{-1e4, -1e4, 1}, {1e4, -1e4, 1}, {1e4, 1e4, 1}, {-1e4, 1e4, 1}};
  const matc::GgxLobe lobe(0.6, 0.4);
  const auto estimate = matc::integrate_polygon_light(lobe, sky, kOne, 1 << 16);
  EXPECT_NEAR(estimate.mean[0], lobe.albedo(256), 4.0 * estimate.standard_error[0] + 1e-4);
  const matc::FresnelAtCosine half = [](double) { return matc::runtime::Rgb{0.5, 0.25, 1.0}; };
  const auto scaled = matc::integrate_polygon_light(lobe, sky, half, 1 << 16);
  EXPECT_DOUBLE_EQ(scaled.mean[0], 0.5 * estimate.mean[0]);
  EXPECT_DOUBLE_EQ(scaled.mean[1], 0.25 * estimate.mean[0]);
  const std::vector<Vec3> quad = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}};
  const auto few = matc::integrate_polygon_light(lobe, quad, kOne, 1 << 10);
  const auto many = matc::integrate_polygon_light(lobe, quad, kOne, 1 << 16);
  EXPECT_LT(many.standard_error[0], few.standard_error[0] / 4.0);
  EXPECT_NEAR(few.mean[0], many.mean[0], 4.0 * few.standard_error[0]);
}

TEST(PolygonLight, ParsesAQuadAndNamesWhatIsWrong) {
  const auto good = matc::parse_polygon_light("-1,-1,2; 1,-1,2; 1,1,2; -1,1,2", 4);
  ASSERT_TRUE(good.error.empty()) << good.error;
  EXPECT_EQ(good.vertices.size(), 4u);
  EXPECT_EQ(good.vertices[1][0], 1.0);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"-1,-1,2;1,-1,2;1,1,2", "expected 4 vertices"},
      {"-1,-1,2;1,-1,2;1,1,2;-1,1", "vertex 4"},
      {"-1,-1,2;1,-1,2;1,x,2;-1,1,2", "\"x\" is not a number"},
      {"-1,-1,2;1,-1,2;1,nan,2;-1,1,2", "finite"},
      {"-1,-1,2;-1,-1,2;1,1,2;-1,1,2", "coincide"},
      {"0,0,1;1,0,1;2,0,1;3,0,1", "no net area"},
      {"-1,-1,2;1,-1,2;1,1,2.5;-1,1,2", "not planar"},
      {"-1,-1,2;1,1,2;1,-1,2;-1,1,2", "crosses itself"},
      {"0,0,2;2,0,2;0.5,0.5,2;0,2,2", "not convex at vertex 3"},
      {"-1,-1,0;1,-1,0;1,1,0;-1,1,0", "edge-on"},
      {"-1,-1,-2;1,-1,-2;1,1,-2;-1,1,-2", "below the horizon"},
  };
  for (const auto& [text, message] : bad) {
    const auto parsed = matc::parse_polygon_light(text, 4);
    EXPECT_NE(parsed.error.find(message), std::string::npos) << text << ": " << parsed.error;
    EXPECT_TRUE(parsed.vertices.empty());
  }
}

}  // namespace
