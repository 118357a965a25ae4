// The random quad lights the LTC fit's polygon objective trains on and docs/ltc.md scores tables
// on: reproducible, valid lights, and a fit to them that beats the L1 fit on quads it never saw.
#include <gtest/gtest.h>

#include <cmath>

#include "matc/ltc/ggx_lobe.h"
#include "matc/ltc/lobe_polygons.h"
#include "matc/ltc/ltc_fit.h"
#include "matc/ltc/polygon_light.h"

namespace {

TEST(LobePolygons, TheSameSeedGivesTheSameValidLights) {
  const matc::GgxLobe lobe(0.4, 0.45);
  const double albedo = lobe.albedo(matc::kLtcFitSamplesPerAxis);
  const std::uint64_t seed = matc::lobe_polygon_seed(matc::kTrainingPolygonSeed, 0.4, 0.45);
  const auto first = matc::lobe_polygons(lobe, albedo, seed, 40, 256);
  const auto again = matc::lobe_polygons(lobe, albedo, seed, 40, 256);
  const auto other = matc::lobe_polygons(
      lobe, albedo, matc::lobe_polygon_seed(matc::kHeldOutPolygonSeed, 0.4, 0.45), 40, 256);
  ASSERT_EQ(first.size(), 40u);
  std::size_t lit = 0, crossing = 0;
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].vertices, again[i].vertices);
    EXPECT_EQ(first[i].share, again[i].share);
    EXPECT_NE(first[i].vertices, other[i].vertices);
    const std::string problem = matc::check_polygon_light(first[i].vertices);
    // Every quad is a light the integrators take, or lies wholly below the horizon.
    bool any_above = false, any_below = false;
    for (const auto& v : first[i].vertices) {
      any_above = any_above || v[2] > 0.0;
      any_below = any_below || v[2] < 0.0;
    }
    if (any_above) {
      EXPECT_EQ(problem, "") << "quad " << i;
    }
    if (any_above && any_below) ++crossing;
    EXPECT_GE(first[i].share, 0.0);
    EXPECT_LE(first[i].share, 1.0 + 4.0 * first[i].share_error);
    if (first[i].share > 0.01) ++lit;
  }
  // Half are centred on the lobe's reflections: many carry a real share of it.
  EXPECT_GE(lit, 15u);
  EXPECT_GE(crossing, 1u);
}

TEST(LtcFit, ThePolygonObjectiveBeatsL1OnQuadsItDidNotSee) {
  for (const auto& [ndotv, roughness] : {std::pair{0.3, 0.5}, std::pair{0.6, 0.35}}) {
    const matc::LtcShape guess{0.25, 0.25, 0.0, -std::acos(ndotv)};
    const matc::LtcCellFit l1 = matc::fit_ltc_cell(ndotv, roughness, guess, false);
    const matc::LtcCellFit polygons =
        matc::fit_ltc_cell(ndotv, roughness, guess, false, matc::LtcObjective::polygons);
    const matc::GgxLobe lobe(ndotv, roughness);
    const auto held_out = matc::lobe_polygons(
        lobe, lobe.albedo(matc::kLtcFitSamplesPerAxis),
        matc::lobe_polygon_seed(matc::kHeldOutPolygonSeed, ndotv, roughness), 64, 2048);
    const double l1_error = matc::ltc_polygon_set_error(l1.inverse, held_out).mean;
    const double polygon_error = matc::ltc_polygon_set_error(polygons.inverse, held_out).mean;
    EXPECT_LT(polygon_error, l1_error) << "NdotV " << ndotv << ", roughness " << roughness;
  }
}

}  // namespace
