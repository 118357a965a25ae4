// Working colour spaces: matrices derived from primaries and whites against the published ones,
// Bradford adaptation, spectral integration into each space, gamut measurement and mapping.
#include <gtest/gtest.h>

#include "compile/compile.h"
#include "optics/color_space.h"
#include "optics/gamut.h"
#include "optics/presets.h"
#include "optics/spectral.h"

namespace matc {
namespace {

void expect_matrix_near(const Matrix3& actual, const Matrix3& expected, double tolerance) {
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      EXPECT_NEAR(actual[i][j], expected[i][j], tolerance) << "row " << i << " column " << j;
}

// The published RGB -> XYZ matrices, quoted to the digits their sources give.
TEST(ColorSpace, DerivedMatricesMatchThePublishedOnes) {
  // ITU-R BT.709 primaries with the D65 chromaticity (0.3127, 0.3290), to 7 digits as
  // colour-science tabulates it (Lindbloom's 0.4124564... uses the rounded XYZ white 0.95047,
  // 1, 1.08883).
  expect_matrix_near(rgb_to_xyz(ColorSpace::lin_rec709),
                     {{{0.4123908, 0.3575843, 0.1804808},
                       {0.2126390, 0.7151687, 0.0721923},
                       {0.0193308, 0.1191948, 0.9505322}}},
                     2e-7);
  // ACES TB-2014-004 (AP1 -> XYZ).
  expect_matrix_near(rgb_to_xyz(ColorSpace::acescg),
                     {{{0.6624541811, 0.1340042065, 0.1561876870},
                       {0.2722287168, 0.6740817658, 0.0536895174},
                       {-0.0055746495, 0.0040607335, 1.0103391003}}},
                     1e-9);
  // ITU-R BT.2087 / BT.2020 (to 7 digits).
  expect_matrix_near(rgb_to_xyz(ColorSpace::lin_rec2020),
                     {{{0.6369580, 0.1446169, 0.1688810},
                       {0.2627002, 0.6779981, 0.0593017},
                       {0.0000000, 0.0280727, 1.0609851}}},
                     2e-7);
  // SMPTE EG 432-1, Display P3 (D65).
  expect_matrix_near(rgb_to_xyz(ColorSpace::lin_displayp3),
                     {{{0.4865709, 0.2656677, 0.1982173},
                       {0.2289746, 0.6917385, 0.0792869},
                       {0.0000000, 0.0451134, 1.0439444}}},
                     2e-7);
}

TEST(ColorSpace, Rec709ToAcescgIsTheBradfordMatrixAcesPublishes) {
  // The linear sRGB -> ACEScg matrix of the ACES OCIO configurations (Bradford, D65 -> ACES).
  expect_matrix_near(rgb_to_rgb(ColorSpace::lin_rec709, ColorSpace::acescg),
                     {{{0.6130974024, 0.3395231462, 0.0473794514},
                       {0.0701937225, 0.9163538791, 0.0134523985},
                       {0.0206155929, 0.1095697729, 0.8698146342}}},
                     2e-6);
}

TEST(ColorSpace, ConversionsKeepWhiteAndInvert) {
  for (const auto& from : color_spaces()) {
    for (const auto& to : color_spaces()) {
      const Matrix3 forward = rgb_to_rgb(from.id, to.id);
      for (const double value : multiply(forward, Rgb{1.0, 1.0, 1.0}))
        EXPECT_NEAR(value, 1.0, 1e-12) << from.name << " -> " << to.name;
      const Matrix3 round_trip = multiply(rgb_to_rgb(to.id, from.id), forward);
      expect_matrix_near(round_trip, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, 1e-12);
    }
  }
}

TEST(ColorSpace, NamesAndAliases) {
  EXPECT_EQ(find_color_space("acescg"), ColorSpace::acescg);
  EXPECT_EQ(find_color_space("lin_ap1"), ColorSpace::acescg);
  EXPECT_EQ(find_color_space("lin_srgb"), ColorSpace::lin_rec709);
  EXPECT_EQ(find_color_space("srgb_texture"), std::nullopt);  // encoded, not a working space
  EXPECT_EQ(color_space_names(), "lin_rec709, acescg, lin_rec2020, lin_displayp3");
}

// Integrating a spectrum into ACEScg and converting to Rec.709 gives what integrating into
// Rec.709 gives: the white adaptation composes, so the two paths differ by rounding only.
TEST(SpectralCurve, EverySpaceRoundTripsToRec709WithinRounding) {
  for (const MetalPreset& preset : metal_presets()) {
    const SpectralCurve rec709(preset_spectrum(preset), ColorSpace::lin_rec709);
    for (const auto& space : color_spaces()) {
      const SpectralCurve other(preset_spectrum(preset), space.id);
      const Matrix3 to_rec709 = rgb_to_rgb(space.id, ColorSpace::lin_rec709);
      for (const double mu : {1.0, 0.5, 0.1}) {
        const Rgb converted = multiply(to_rec709, other.at(mu));
        const Rgb direct = rec709.at(mu);
        for (std::size_t c = 0; c < 3; ++c)
          EXPECT_NEAR(converted[c], direct[c], 1e-12) << preset.symbol << " " << space.name;
      }
    }
  }
}

TEST(SpectralCurve, PerfectMirrorIsWhiteInEverySpace) {
  const Spectrum mirror{{300.0, 900.0}, {0.0, 0.0}, {5.0, 5.0}};
  for (const auto& space : color_spaces())
    for (const double value : SpectralCurve(mirror, space.id).at(1.0))
      EXPECT_NEAR(value, 1.0, 1e-12) << space.name;
}

Material gold() {
  Material material;
  material.name = "gold";
  SpectralInput input;
  input.preset = "Au";
  input.spectrum = preset_spectrum(*find_metal_preset("Au"));
  material.model = input;
  return material;
}

TEST(Gamut, GoldLeavesRec709AndStaysInsideAcescg) {
  const CompiledMaterial rec709 = compile_material(gold(), runtime::shipped_basis());
  EXPECT_FALSE(rec709.range.within_unit_range());
  EXPECT_GT(rec709.range.max[0], 1.03);  // gold's measured red is outside Rec.709
  const CompiledMaterial acescg =
      compile_material(gold(), runtime::shipped_basis(), {ColorSpace::acescg, GamutMapping::none});
  EXPECT_TRUE(acescg.range.within_unit_range());
}

TEST(Gamut, DesaturationBringsTheCurveIntoRangeAndKeepsLuminanceAndGrazingWhite) {
  const ColorOptions options{ColorSpace::lin_rec709, GamutMapping::desaturate};
  const CompiledMaterial mapped = compile_material(gold(), runtime::shipped_basis(), options);
  EXPECT_LT(mapped.saturation, 1.0);
  EXPECT_GT(mapped.saturation, 0.8);
  const auto original = make_working_space_curve(gold(), ColorSpace::lin_rec709);
  const auto curve = make_reflectance_curve(gold(), options);
  const CurveRange range = measure_curve_range(*curve);
  EXPECT_TRUE(range.within_unit_range());
  EXPECT_NEAR(*std::max_element(range.max.begin(), range.max.end()), 1.0, 1e-12);
  const Rgb luminance = rgb_to_xyz(ColorSpace::lin_rec709)[1];
  for (const double mu : {0.0, 0.2, 0.7, 1.0}) {
    const Rgb a = original->at(mu);
    const Rgb b = curve->at(mu);
    const double ya = luminance[0] * a[0] + luminance[1] * a[1] + luminance[2] * a[2];
    const double yb = luminance[0] * b[0] + luminance[1] * b[1] + luminance[2] * b[2];
    EXPECT_NEAR(ya, yb, 1e-12);
  }
  for (const double value : curve->at(0.0))
    EXPECT_NEAR(value, 1.0, 1e-12);
  // A curve already in range is left exactly as it is.
  Material aluminium = gold();
  std::get<SpectralInput>(aluminium.model).spectrum = preset_spectrum(*find_metal_preset("Al"));
  EXPECT_EQ(compile_material(aluminium, runtime::shipped_basis(), options).saturation, 1.0);
}

TEST(ColorSpace, MaterialSpaceConvertsRgbInputsToTheWorkingSpace) {
  Material in_acescg;
  in_acescg.name = "m";
  in_acescg.model = F82TintInput{{0.9, 0.6, 0.3}, {0.8, 0.9, 1.0}};
  in_acescg.color_space = ColorSpace::acescg;
  const auto converted = make_working_space_curve(in_acescg, ColorSpace::lin_rec709);
  const F82TintCurve original({0.9, 0.6, 0.3}, {0.8, 0.9, 1.0});
  const Matrix3 to_rec709 = rgb_to_rgb(ColorSpace::acescg, ColorSpace::lin_rec709);
  for (const double mu : {0.05, 0.5, 1.0}) {
    const Rgb expected = multiply(to_rec709, original.at(mu));
    const Rgb actual = converted->at(mu);
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(actual[c], expected[c], 1e-15);
  }
  // In its own space nothing changes, and the per-channel IOR is reported only without mixing.
  const auto same = make_working_space_curve(in_acescg, ColorSpace::acescg);
  EXPECT_EQ(same->at(0.5), original.at(0.5));
}

}  // namespace
}  // namespace matc
