// A filmed metal under a coat (docs/thin-film.md "Under a coat"): the film lies between the coat
// and the metal, so it is seen from the coat's medium, and its table holds the whole base lobe.
// Checked against the exact layered curve (optics/coat.h's LayeredCurve over the film in air and
// the film under the coat) and against the split-sum layering with exact curves
// (lut/layered_reference.h), on measured titanium and gold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "compile/compile.h"
#include "lut/layered_reference.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/shipped_bases.h"
#include "optics/coat.h"
#include "optics/presets.h"
#include "optics/thin_film.h"
#include "preset_material.h"

namespace matc {
namespace {

Material filmed_under_coat(const char* preset, FilmInput film, CoatInput coat) {
  Material material = test::preset_material(*find_metal_preset(preset), preset);
  material.film = film;
  material.coat = coat;
  return material;
}

double largest(const Rgb& a, const Rgb& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// A film of the coat's own index under a full coat is more coat: the coated bare metal, bit for
// bit. One of index 1 there is an air gap between coat and metal, which shows.
TEST(FilmUnderCoat, OfTheCoatsIndexIsMoreCoatButAnAirGapShows) {
  const auto& basis = runtime::shipped_basis();
  CoatInput coat;
  coat.ior = 1.5;
  Material bare = test::preset_material(*find_metal_preset("Ti"), "Ti");
  bare.coat = coat;
  const CompiledMaterial coated = compile_material(bare, basis);
  const CompiledMaterial same =
      compile_material(filmed_under_coat("Ti", {1.0, 1.5, 300.0}, coat), basis);
  EXPECT_FALSE(same.film_table);
  EXPECT_EQ(same.coat->coefficients.under_coat, coated.coat->coefficients.under_coat);
  const CompiledMaterial gap =
      compile_material(filmed_under_coat("Ti", {1.0, 1.0, 300.0}, coat), basis);
  EXPECT_TRUE(gap.film_table);
  // Under a partial coat the film of the coat's index still shows in the uncoated part.
  coat.weight = 0.5;
  EXPECT_TRUE(compile_material(filmed_under_coat("Ti", {1.0, 1.5, 300.0}, coat), basis).film_table);
}

struct Case {
  const char* metal;
  FilmInput film;
  CoatInput coat;
};

class FilmUnderCoatTable : public ::testing::TestWithParam<Case> {};

// The table's F row is the exact layered base lobe; with the coat lobe from its coefficients, both
// lobes are within the coat's own fit (0.002) of the exact layered curve. The 4-term fit of the
// filmed metal seen through the coat, what a coated metal's shaders would use, misses it.
TEST_P(FilmUnderCoatTable, HoldsTheExactLayeredBase) {
  const Case& given = GetParam();
  const auto& basis = runtime::shipped_basis();
  const CompiledMaterial compiled =
      compile_material(filmed_under_coat(given.metal, given.film, given.coat), basis);
  ASSERT_TRUE(compiled.film_table);
  ASSERT_TRUE(compiled.coat);
  EXPECT_LT(worst_channel(compiled.film_table_error.max_abs), 0.004);
  EXPECT_LT(worst_channel(compiled.coat->layered_error.max_abs), 0.0035);
  EXPECT_GT(worst_channel(compiled.coat->under_coat_error.max_abs), 0.01);

  // The base lobe against the direct layering of the exact curves, film in air and under the coat.
  const auto in_air = make_reflectance_curve(compiled.material, compiled.color);
  const auto under = make_under_coat_curve(compiled.material, compiled.color.working_space);
  const LayeredCurve base(*in_air, *under, given.coat.weight, given.coat.ior, given.coat.color,
                          LayeredCurve::Part::base);
  for (const double mu : {1.0, 0.7, 0.4, 0.2, 0.08})
    EXPECT_LT(largest(runtime::film_fresnel(*compiled.film_table, mu), base.at(mu)), 0.004) << mu;

  // Fbar between the nodes against the split-sum layering of the exact curves: the film table's
  // own bound (FilmTables.*), and the coat lobe's from the preintegrated table.
  const TabulatedCurve in_air_exact(*in_air), under_exact(*under);
  for (const double ndotv : {0.93, 0.55, 0.23}) {
    for (const double roughness : {0.12, 0.41, 0.77}) {
      const Rgb reference =
          layered_split_sum(in_air_exact, under_exact, given.coat, ndotv, roughness);
      const double coat_fbar =
          given.coat.weight *
          SplitSumEstimator(ndotv, given.coat.roughness).integrate(CoatCurve(given.coat.ior))[0];
      Rgb ours = runtime::film_preintegrated(*compiled.film_table, ndotv, roughness);
      for (double& channel : ours)
        channel += coat_fbar;
      EXPECT_LT(largest(ours, reference), 0.006) << ndotv << " " << roughness;
    }
  }
}

CoatInput coat_of(double ior, double roughness, double weight = 1.0, Rgb color = {1, 1, 1}) {
  CoatInput coat;
  coat.ior = ior;
  coat.roughness = roughness;
  coat.weight = weight;
  coat.color = color;
  return coat;
}

INSTANTIATE_TEST_SUITE_P(
    MeasuredMetals, FilmUnderCoatTable,
    ::testing::Values(Case{"Ti", {1.0, 2.3, 300.0}, coat_of(1.5, 0.1)},
                      // A film of lower index than its coat: evanescent past its critical angle.
                      Case{"Au", {1.0, 1.3, 500.0}, coat_of(1.6, 0.3)},
                      Case{"Ti", {0.8, 2.4, 45.0}, coat_of(1.5, 0.2, 0.6, {0.95, 0.85, 0.6})}));

}  // namespace
}  // namespace matc
