// The F0 table of a textured metal under an edge colour or a coat (compile/f0_table.h,
// matc/runtime/f0_table.h): its entries are the compile at their F0, and a pixel's coefficients
// interpolated from them stay within the fit's own error of the compile at the pixel's F0, at
// every level an 8-bit sRGB base colour texture holds.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "bake/image_map.h"  // srgb_to_linear: how the bake decodes an 8-bit sRGB map
#include "compile/f0_table.h"
#include "matc/runtime/shipped_bases.h"
#include "sanitized_build.h"

namespace matc {
namespace {

Material metal(const Rgb& f0, const Rgb& tint, std::optional<CoatInput> coat) {
  Material material;
  material.name = "textured";
  material.model = F82TintInput{f0, tint};
  material.coat = coat;
  return material;
}

TEST(F0Table, EntriesAreTheCompileAtTheirF0) {
  const runtime::BasisView& basis = runtime::shipped_basis(runtime::kDefaultBasis);
  const Material coated =
      metal({0.9, 0.8, 0.6}, {0.7, 0.9, 1.0}, CoatInput{0.8, 1.5, 0.1, {1, 1, 1}});
  const runtime::F0Table table = compile_f0_table(coated, basis, {});
  ASSERT_TRUE(table.under_coat);
  for (const std::size_t entry : {std::size_t{0}, std::size_t{7}, runtime::kF0TableEntries - 1}) {
    const double f0 = runtime::f0_table_entry_f0(entry);
    const CompiledMaterial compiled =
        compile_material(metal({f0, f0, f0}, {0.7, 0.9, 1.0}, coated.coat), basis);
    EXPECT_EQ(table.in_air[entry], compiled.coefficients) << entry;
    EXPECT_EQ((*table.under_coat)[entry], compiled.coat->coefficients.under_coat) << entry;
    // At an entry the runtime's interpolation returns it (c_0, c_1 in air: F0, 1 - F0).
    const runtime::Coefficients air = runtime::coefficients_from_f0_table(table, {f0, f0, f0});
    const runtime::Coefficients under =
        runtime::under_coat_coefficients_from_f0_table(table, {f0, f0, f0});
    for (std::size_t c = 0; c < 3; ++c) {
      for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(air[c][i], compiled.coefficients[c][i], 1e-12) << entry << " " << c << i;
        EXPECT_NEAR(under[c][i], compiled.coat->coefficients.under_coat[c][i], 1e-12);
      }
    }
  }
  EXPECT_EQ(runtime::f0_table_entry_f0(0), 0.0);
  EXPECT_EQ(runtime::f0_table_entry_f0(runtime::kF0TableEntries - 1), 1.0);
  EXPECT_FALSE(compile_f0_table(metal({0.9, 0.8, 0.6}, {0.7, 0.9, 1.0}, {}), basis, {}).under_coat);
}

// The levels of an 8-bit texture where the table is weakest (the darkest 32, where a coat moves
// the coefficients fastest) and every 8th above: bench/f0_table_accuracy reads all 256.
std::vector<double> texture_levels() {
  std::vector<double> f0s;
  for (int level = 0; level < 256; level += level < 32 ? 1 : 8)
    f0s.push_back(srgb_to_linear(level / 255.0));
  return f0s;
}

F0TableError table_error(const Rgb& tint, std::optional<CoatInput> coat) {
  return measure_f0_table(metal({0.5, 0.5, 0.5}, tint, coat),
                          runtime::shipped_basis(runtime::kDefaultBasis), {}, texture_levels());
}

// Nearly linear in F0 (Schlick's curve is; the edge colour's dip scales with F0 too): a fraction
// of the fit's own error.
TEST(F0Table, BareEdgeColouredMetalFollowsTheCompileClosely) {
  const F0TableError error = table_error({0.6, 0.8, 1.0}, std::nullopt);
  EXPECT_LT(error.table, 1e-3);
  EXPECT_LT(error.table, error.fit / 10) << "fit's own: " << error.fit;
}

TEST(F0Table, CoatedMetalsFollowTheCompileWithinTheFitsOwnError) {
  // Under the sanitizers (21 s for all six) glTF's default coat with an edge colour stands for the
  // others: the code is the same.
  for (const double ior : {1.5, 1.3, 1.6}) {
    for (const Rgb tint : {Rgb{0.7, 0.9, 1.0}, Rgb{1, 1, 1}}) {
      if (test::kSanitizedBuild && (ior != 1.5 || tint[0] == 1.0)) continue;
      const F0TableError error = table_error(tint, CoatInput{1.0, ior, 0.0, {1, 1, 1}});
      EXPECT_LT(error.table, error.fit) << "coat " << ior << " tint " << tint[0];
      EXPECT_LT(error.table, 0.01) << "coat " << ior << " tint " << tint[0];
    }
  }
}

// A texture's F0 can be anything: outside [0, 1] it is clamped, NaN reads as 0 (as the runtime's
// other per-pixel inputs), and a bare metal's table has no under-coat entries to read.
TEST(F0Table, ClampsHostileF0AndRefusesUnderCoatOfABareMetal) {
  const runtime::BasisView& basis = runtime::shipped_basis(runtime::kDefaultBasis);
  const runtime::F0Table bare =
      compile_f0_table(metal({0.5, 0.5, 0.5}, {0.7, 0.9, 1.0}, std::nullopt), basis, {});
  const runtime::Coefficients hostile =
      runtime::coefficients_from_f0_table(bare, {std::nan(""), -3.0, 7.0});
  const runtime::Coefficients clamped = runtime::coefficients_from_f0_table(bare, {0.0, 0.0, 1.0});
  EXPECT_EQ(hostile, clamped);
  EXPECT_EQ(clamped[0][0], 0.0);
  EXPECT_EQ(clamped[2][0], 1.0);
  for (std::size_t i = 2; i < 4; ++i) {
    EXPECT_EQ(clamped[0][i], bare.in_air.front()[0][i]);
    EXPECT_EQ(clamped[2][i], bare.in_air.back()[2][i]);
  }
  EXPECT_THROW(runtime::under_coat_coefficients_from_f0_table(bare, {0.5, 0.5, 0.5}),
               std::logic_error);
}

TEST(F0Table, OnlyWhereEachChannelIsItsOwn) {
  Material edge = metal({0.9, 0.8, 0.6}, {0.7, 0.9, 1.0}, std::nullopt);
  edge.color_space = ColorSpace::lin_rec709;  // as glTF import writes it
  EXPECT_TRUE(has_f0_table(edge, {}));
  EXPECT_FALSE(has_f0_table(edge, {ColorSpace::acescg, GamutMapping::none}));
  EXPECT_FALSE(has_f0_table(edge, {kDefaultColorSpace, GamutMapping::desaturate}));
  Material artistic = edge;
  artistic.model = ArtisticInput{{0.9, 0.8, 0.6}, {0.5, 0.5, 0.5}};
  EXPECT_FALSE(has_f0_table(artistic, {}));
  EXPECT_THROW(compile_f0_table(artistic, runtime::shipped_basis(runtime::kDefaultBasis), {}),
               std::logic_error);
}

}  // namespace
}  // namespace matc
