// The random quad lights the LTC fit's polygon objective trains on and docs/ltc.md scores tables
// on: reproducible, valid lights, and a fit to them that beats the L1 fit on quads it never saw.
#include <gtest/gtest.h>

#include <cmath>

#include "ltc/ggx_lobe.h"
#include "ltc/lobe_polygons.h"
#include "ltc/ltc_fit.h"
#include "ltc/polygon_light.h"

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
  // One row of a 16 x 16 table at roughness 0.4, both objectives, scored on held-out quads: over
  // the row (one texel can go either way; docs/ltc.md has the whole table).
  constexpr std::size_t kSize = 16, kRow = 6;
  const matc::LtcTable l1 =
      matc::fit_ltc_table({.size = kSize, .objective = matc::LtcObjective::l1}, kRow, 1);
  const matc::LtcTable polygons =
      matc::fit_ltc_table({.size = kSize, .objective = matc::LtcObjective::polygons}, kRow, 1);
  double l1_error = 0.0, polygon_error = 0.0;
  for (std::size_t x = 0; x < kSize; ++x) {
    const double ndotv = matc::ltc_texel_ndotv(x, kSize);
    const double roughness = matc::ltc_texel_roughness(kRow, kSize);
    const matc::GgxLobe lobe(ndotv, roughness);
    const auto held_out = matc::lobe_polygons(
        lobe, lobe.albedo(matc::kLtcFitSamplesPerAxis),
        matc::lobe_polygon_seed(matc::kHeldOutPolygonSeed, ndotv, roughness), 32, 4096);
    const auto inverse = [&](const matc::LtcTable& table) {
      const auto t = table.view().texel(x, kRow);
      return matc::runtime::LtcInverse{t[0], t[1], t[2], t[3]};
    };
    l1_error += matc::ltc_polygon_set_error(inverse(l1), held_out).mean;
    polygon_error += matc::ltc_polygon_set_error(inverse(polygons), held_out).mean;
  }
  EXPECT_LT(polygon_error, 0.95 * l1_error)
      << "polygon objective " << polygon_error << ", L1 " << l1_error;
}

}  // namespace
