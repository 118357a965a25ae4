// A thickness per pixel (compile/film_tables.h's bake_film_stack, read by runtime/film_table.h's
// film_stack_*; docs/thin-film.md "A thickness per pixel"): the texture's layout, the reads the
// shaders make, and the films between the slices against the exact film curve and a Monte-Carlo
// split sum of it. The targets are 0.01 for F and for Fbar; the measured metals below
// stay within 0.0017 and 0.0024 (F within 0.004 and Fbar within 0.006 are held, as FilmTables.*).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "compile/compile.h"
#include "compile/film_tables.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/film_table.h"
#include "matc/runtime/shipped_bases.h"
#include "optics/presets.h"
#include "optics/thin_film.h"
#include "preset_material.h"

namespace matc {
namespace {

using runtime::FilmStack;
using runtime::FilmTable;

double worst_channel(const Rgb& a, const Rgb& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// Slice s holds s + x / 100 in red and s + (y + 1) / 100 in green at column x, row y.
FilmStack numbered_stack(std::size_t slices) {
  FilmStack stack{100.0, 400.0, std::vector<FilmTable>(slices)};
  for (std::size_t s = 0; s < slices; ++s) {
    const double slice = static_cast<double>(s);
    FilmTable& table = stack.slices[s];
    table.preintegrated.resize(FilmTable::kViewNodes * FilmTable::kRoughnessNodes);
    for (std::size_t x = 0; x < FilmTable::kWidth; ++x) {
      const double column = 0.01 * static_cast<double>(x);
      table.fresnel[x] = {slice + column, slice, 0.5};
      // preintegrated is NdotV fastest.
      for (std::size_t j = 0; j < FilmTable::kRoughnessNodes; ++j)
        table.preintegrated[j * FilmTable::kViewNodes + x] = {
            slice + column, slice + 0.01 * static_cast<double>(j + 1), 0.5};
    }
  }
  return stack;
}

TEST(FilmStack, OneSliceIsTheFilmTablesTexture) {
  const FilmStack one = numbered_stack(1);
  EXPECT_EQ(runtime::film_stack_texels(one), runtime::film_table_texels(one.slices[0]));
  EXPECT_EQ(runtime::film_stack_height(one), FilmTable::kHeight);
}

// Rows 0 to N - 1 each slice's F; then for roughness node j the N rows of Fbar, slice by slice.
TEST(FilmStack, TextureStacksTheFRowsThenEachRoughnessNodesRows) {
  constexpr std::size_t kSlices = 3;
  const FilmStack stack = numbered_stack(kSlices);
  ASSERT_EQ(runtime::film_stack_height(stack), 18 * kSlices);
  const std::vector<float> texels = runtime::film_stack_texels(stack);
  ASSERT_EQ(texels.size(), FilmTable::kWidth * 18 * kSlices * 4);
  const auto texel = [&](std::size_t x, std::size_t row, std::size_t channel) {
    return texels[4 * (row * FilmTable::kWidth + x) + channel];
  };
  EXPECT_FLOAT_EQ(texel(7, 2, 0), 2.07f);                      // slice 2's F
  EXPECT_FLOAT_EQ(texel(7, 2, 1), 2.0f);                       // an F row
  EXPECT_FLOAT_EQ(texel(5, kSlices + 1, 1), 1.01f);            // roughness node 0, slice 1
  EXPECT_FLOAT_EQ(texel(5, kSlices + 4 * kSlices, 1), 0.05f);  // roughness node 4, slice 0
  EXPECT_FLOAT_EQ(texel(64, 18 * kSlices - 1, 1), 2.17f);      // roughness node 16, slice 2
  EXPECT_EQ(texels.back(), 1.0f);                              // alpha
}

// Linear over the thickness coordinate between slices; clamped, NaN read as 0, as a sampler.
TEST(FilmStack, ReadsLinearlyOverTheThickness) {
  const FilmStack stack = numbered_stack(3);
  const double mu = runtime::film_table_cosine(10);
  // The ends are held kFilmStackInset of a slice inside, as the shaders hold them.
  constexpr double kInset = runtime::kFilmStackInset;
  EXPECT_DOUBLE_EQ(runtime::film_stack_fresnel(stack, mu, 0.0)[1], kInset);
  EXPECT_DOUBLE_EQ(runtime::film_stack_fresnel(stack, mu, 1.0)[1], 2.0 - kInset);
  EXPECT_DOUBLE_EQ(runtime::film_stack_fresnel(stack, mu, 0.25)[1], 0.5);
  EXPECT_DOUBLE_EQ(runtime::film_stack_fresnel(stack, mu, 0.75)[0], 1.6);
  EXPECT_DOUBLE_EQ(runtime::film_stack_fresnel(stack, mu, -3.0)[1], kInset);
  EXPECT_DOUBLE_EQ(runtime::film_stack_fresnel(stack, mu, 7.0)[1], 2.0 - kInset);
  EXPECT_DOUBLE_EQ(runtime::film_stack_fresnel(stack, mu, std::nan(""))[1], kInset);
  // Image light: trilinear, the roughness node 4 of slices 0 and 1 halfway.
  const double ndotv = runtime::film_table_view_cosine(20);
  const Rgb image =
      runtime::film_stack_preintegrated(stack, ndotv, runtime::film_table_roughness(4), 0.25);
  EXPECT_NEAR(image[0], 0.5 + 0.2, 1e-12);
  EXPECT_NEAR(image[1], 0.5 + 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(runtime::film_stack_thickness(stack, 1), 250.0);
  // One film's table at a thickness reads as the stack does there.
  const FilmTable between = runtime::film_stack_table_at(stack, 0.3);
  EXPECT_NEAR(runtime::film_fresnel(between, mu)[1], runtime::film_stack_fresnel(stack, mu, 0.3)[1],
              1e-15);
  EXPECT_NEAR(runtime::film_preintegrated(between, ndotv, 0.4)[1],
              runtime::film_stack_preintegrated(stack, ndotv, 0.4, 0.3)[1], 1e-15);
}

Material titanium_with(FilmInput film) {
  Material material = test::preset_material(*find_metal_preset("Ti"), "titanium");
  material.film = film;
  return material;
}

// The stack's last slice is the film at the range's maximum, what a film of that one thickness
// compiles to (within the sweep's rounding): whatever reads the material without a texture sees
// glTF's maximum.
TEST(FilmStackCompile, LastSliceIsTheFilmAtTheMaximum) {
  const auto& basis = runtime::shipped_basis();
  FilmInput range{1.0, 2.3, 400.0};
  range.thickness_minimum_nm = 100.0;
  const CompiledMaterial stacked = compile_material(titanium_with(range), basis);
  const CompiledMaterial fixed = compile_material(titanium_with({1.0, 2.3, 400.0}), basis);
  ASSERT_TRUE(stacked.film_stack && stacked.film_table && fixed.film_table);
  EXPECT_FALSE(fixed.film_stack);
  // The stack's rows come from the film's sweep, within 1e-12 of each film's own sum.
  for (std::size_t i = 0; i < FilmTable::kCosineNodes; ++i) {
    EXPECT_LT(worst_channel(stacked.film_table->fresnel[i], fixed.film_table->fresnel[i]), 1e-12);
    EXPECT_EQ(stacked.film_stack->slices.back().fresnel[i], stacked.film_table->fresnel[i]);
  }
  for (std::size_t n = 0; n < fixed.film_table->preintegrated.size(); ++n) {
    EXPECT_LT(
        worst_channel(stacked.film_table->preintegrated[n], fixed.film_table->preintegrated[n]),
        1e-12);
  }
  EXPECT_EQ(stacked.coefficients, fixed.coefficients);
  const runtime::FilmTable first =
      bake_film_table(ThinFilmCurve(preset_spectrum(*find_metal_preset("Ti")), {2.3, 100.0}));
  for (std::size_t i = 0; i < FilmTable::kCosineNodes; ++i)
    EXPECT_LT(worst_channel(stacked.film_stack->slices.front().fresnel[i], first.fresnel[i]),
              1e-12);
  EXPECT_LE(stacked.film_stack_error, kFilmStackTarget);
  Diagnostics diagnostics;
  warn_if_poor_fit(stacked, diagnostics);
  EXPECT_TRUE(diagnostics.items().empty());
}

// A range too wide for the slices the texture may hold is compiled, with a warning that says how
// close it is and what to do.
TEST(FilmStackCompile, ARangeTooWideForItsSlicesIsWarnedOf) {
  FilmInput range{1.0, 2.5, 1000.0};
  range.thickness_minimum_nm = 0.0;
  const CompiledMaterial compiled =
      compile_material(titanium_with(range), runtime::shipped_basis());
  ASSERT_TRUE(compiled.film_stack);
  EXPECT_LE(compiled.film_stack->slices.size(), kMaxFilmStackSlices);
  EXPECT_GT(compiled.film_stack_error, kPoorFilmStackError);
  Diagnostics diagnostics;
  warn_if_poor_fit(compiled, diagnostics);
  ASSERT_EQ(diagnostics.items().size(), 1u);
  EXPECT_NE(diagnostics.items()[0].message.find("thickness range 0-1000 nm"), std::string::npos);
}

// A film curve's sweep over thicknesses (what the compile's stacks are made of) is each film's own
// sum: spectral and per-channel metals, partial coverage, grazing, an evanescent film.
TEST(FilmStackCompile, ASweepIsEachFilmsSum) {
  const Spectrum& titanium = preset_spectrum(*find_metal_preset("Ti"));
  const std::array<ComplexIor, 3> gold = {ComplexIor{0.18, 3.4}, ComplexIor{0.42, 2.35},
                                          ComplexIor{1.37, 1.77}};
  // The third is a film under a coat of higher index (film_under_coat): past its critical angle
  // (cosines below 0.6) its wave does not propagate, and each thickness is its own sum.
  for (const ThinFilm film :
       {ThinFilm{2.3, 0.0, 1.0}, ThinFilm{1.3, 0.0, 0.6}, ThinFilm{0.8, 0.0, 1.0}}) {
    const ThinFilmCurve spectral(titanium, film);
    const ThinFilmChannelCurve channels(gold, film, kDefaultColorSpace);
    for (const double mu : {0.0, 0.013, 0.4, 1.0}) {
      std::vector<Rgb> swept(160), channel_swept(160);
      spectral.sweep_thickness(mu, 7.5, 6.25, swept);
      channels.sweep_thickness(mu, 7.5, 6.25, channel_swept);
      for (std::size_t k = 0; k < swept.size(); ++k) {
        ThinFilm at = film;
        at.thickness_nm = 7.5 + 6.25 * static_cast<double>(k);
        EXPECT_LT(worst_channel(swept[k], ThinFilmCurve(titanium, at).at(mu)), 1e-12) << k;
        EXPECT_LT(worst_channel(channel_swept[k],
                                ThinFilmChannelCurve(gold, at, kDefaultColorSpace).at(mu)),
                  1e-12)
            << k;
      }
    }
  }
}

struct StackCase {
  const char* metal;
  double ior;
  double minimum_nm;
  double maximum_nm;
};

class FilmStackTest : public ::testing::TestWithParam<StackCase> {};

// Between the slices, at thicknesses on no node: F against the exact film over cosines 0.05-1, and
// Fbar against a Monte-Carlo split sum of the exact film at points between the nodes.
TEST_P(FilmStackTest, HoldsTheFilmsBetweenItsSlices) {
  const StackCase& given = GetParam();
  const Spectrum& metal = preset_spectrum(*find_metal_preset(given.metal));
  // A curve per thickness here; the compile's sweep is held to it below.
  const BakedFilmStack baked =
      bake_film_stack(film_rows_by_curve([&](double nm) {
                        return std::make_unique<ThinFilmCurve>(metal, ThinFilm{given.ior, nm});
                      }),
                      given.minimum_nm, given.maximum_nm);
  EXPECT_LE(baked.thickness_error, kFilmStackTarget);
  const double span = given.maximum_nm - given.minimum_nm;
  double direct = 0.0, image = 0.0;
  for (const double t : {0.0113, 0.2871, 0.5037, 0.7462, 0.9931}) {
    const ThinFilmCurve exact(metal, {given.ior, given.minimum_nm + t * span});
    for (int j = 0; j <= 190; ++j) {
      const double mu = 0.05 + 0.005 * j;
      direct = std::max(
          direct, worst_channel(runtime::film_stack_fresnel(baked.stack, mu, t), exact.at(mu)));
    }
    const TabulatedCurve curve(exact);
    for (const double ndotv : {0.093, 0.41, 0.87}) {
      for (const double roughness : {0.08, 0.33, 0.71}) {
        const SplitSumEstimator reference(ndotv, roughness, 8192);
        image = std::max(image, worst_channel(runtime::film_stack_preintegrated(baked.stack, ndotv,
                                                                                roughness, t),
                                              reference.integrate(curve)));
      }
    }
  }
  EXPECT_LT(direct, 0.004) << given.metal << " " << given.ior;
  EXPECT_LT(image, 0.006) << given.metal << " " << given.ior;
}

// glTF's default film (index 1.3, 100-400 nm) and the anodised-titanium range of a heat-tint
// gradient.
INSTANTIATE_TEST_SUITE_P(MeasuredMetals, FilmStackTest,
                         ::testing::Values(StackCase{"Au", 1.3, 100.0, 400.0},
                                           StackCase{"Ti", 2.3, 20.0, 250.0},
                                           StackCase{"Cu", 1.8, 150.0, 450.0}));

}  // namespace
}  // namespace matc
