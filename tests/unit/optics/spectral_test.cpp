// Spectral materials: CIE/D65 integration to linear sRGB, presets, and n,k CSV validation.
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <ostream>

#include "optics/presets.h"
#include "optics/spectral.h"

namespace matc {
namespace {

Spectrum constant_spectrum(double n, double k) {
  return {{300.0, 900.0}, {n, n}, {k, k}};
}

TEST(SpectralCurve, PerfectMirrorMapsToWhite) {
  // n = 0 gives F = 1 at normal incidence for any k.
  const SpectralCurve mirror(constant_spectrum(0.0, 5.0));
  for (const double value : mirror.at(1.0))
    EXPECT_NEAR(value, 1.0, 1e-12);
}

TEST(SpectralCurve, GreySpectrumEqualsSingleIorCurve) {
  const SpectralCurve spectral(constant_spectrum(1.3, 4.2));
  for (int j = 0; j <= 20; ++j) {
    const double mu = j / 20.0;
    const double expected = fresnel_exact(mu, {1.3, 4.2});
    for (const double value : spectral.at(mu))
      EXPECT_NEAR(value, expected, 1e-12);
  }
}

// F0 in linear sRGB of every preset as published in compiler/data/SOURCES.md (computed there by an
// independent script that reproduces Real-Time Rendering 4th ed. Table 9.2 to 0.001).
TEST(Presets, NormalIncidenceColourMatchesPublishedTable) {
  const std::map<std::string, Rgb> published = {
      {"Ag", {0.989, 0.984, 0.978}}, {"Al", {0.907, 0.916, 0.922}},   {"Au", {1.038, 0.728, 0.365}},
      {"Be", {0.539, 0.538, 0.537}}, {"Co", {0.683, 0.655, 0.616}},   {"Cr", {0.550, 0.556, 0.554}},
      {"Cu", {0.932, 0.623, 0.522}}, {"CuZn", {0.910, 0.778, 0.423}}, {"Fe", {0.530, 0.513, 0.494}},
      {"Hg", {0.781, 0.779, 0.778}}, {"Ir", {0.701, 0.693, 0.656}},   {"K", {0.949, 0.938, 0.921}},
      {"Li", {0.935, 0.902, 0.824}}, {"Mo", {0.559, 0.579, 0.570}},   {"Na", {0.982, 0.966, 0.924}},
      {"Ni", {0.697, 0.640, 0.563}}, {"Pd", {0.733, 0.697, 0.652}},   {"Pt", {0.761, 0.730, 0.683}},
      {"Rh", {0.797, 0.765, 0.742}}, {"Ta", {0.389, 0.360, 0.412}},   {"Ti", {0.619, 0.579, 0.543}},
      {"V", {0.520, 0.535, 0.567}},  {"W", {0.515, 0.496, 0.468}},    {"Zn", {0.743, 0.769, 0.768}},
  };
  ASSERT_EQ(metal_presets().size(), published.size());
  for (const MetalPreset& preset : metal_presets()) {
    const Rgb f0 = SpectralCurve(preset_spectrum(preset)).at(1.0);
    const Rgb& expected = published.at(std::string(preset.symbol));
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(f0[c], expected[c], 0.0006) << preset.symbol << " channel " << c;
    }
  }
}

TEST(Presets, GoldIsNotTheFresnelOfThreeWavelengths) {
  // The RGB shortcut (n, k at ~650/550/450 nm) is what the spectral integral replaces.
  const Spectrum& gold = preset_spectrum(*find_metal_preset("Au"));
  const Rgb integrated = SpectralCurve(gold).at(1.0);
  const double shortcut_red = fresnel_exact(1.0, gold.at(650.0));
  EXPECT_GT(std::abs(integrated[0] - shortcut_red), 0.05);
}

TEST(Presets, OnlyZincCarriesACaveat) {
  for (const MetalPreset& preset : metal_presets()) {
    EXPECT_EQ(preset.caveat.empty(), preset.symbol != "Zn") << preset.symbol;
  }
  EXPECT_EQ(find_metal_preset("Xx"), nullptr);
}

struct CsvCase {
  std::string name;
  std::string text;
  std::string expected;  // a substring of the first diagnostic, position included
};

// Names the case in test output instead of dumping its bytes.
void PrintTo(const CsvCase& c, std::ostream* os) {
  *os << c.name;
}

class NkCsvErrors : public testing::TestWithParam<CsvCase> {};

TEST_P(NkCsvErrors, AreReportedWithPosition) {
  const CsvCase& c = GetParam();
  Diagnostics diagnostics;
  EXPECT_FALSE(parse_nk_csv(c.text, TextLocator("nk.csv", c.text), diagnostics).has_value());
  ASSERT_TRUE(diagnostics.has_errors());
  EXPECT_NE(format_diagnostic(diagnostics.items().front()).find(c.expected), std::string::npos)
      << format_diagnostic(diagnostics.items().front());
}

INSTANTIATE_TEST_SUITE_P(
    Spectrum, NkCsvErrors,
    testing::Values(
        CsvCase{"Empty", "", "nk.csv: error: holds no data rows"},
        CsvCase{"HeaderOnly", "wavelength_nm,n,k\n", "holds no data rows"},
        CsvCase{"Micrometres", "wavelength_um,n,k\n0.4,1,2\n", "nk.csv:1:1: error: header"},
        CsvCase{"NotANumber", "380,1,2\n400,abc,2\n", "nk.csv:2:5: error: value: 'abc'"},
        CsvCase{"TooFewFields", "380,1,2\n400,1\n", "nk.csv:2:1: error: row: has 2 fields"},
        CsvCase{"Unsorted", "380,1,2\n700,1,2\n600,1,2\n800,1,2\n",
                "nk.csv:3:1: error: wavelength_nm: 600 does not follow 700"},
        CsvCase{"NegativeK", "380,1,2\n800,1,-2\n", "nk.csv:2:7: error: k: -2 is out of range"},
        CsvCase{"Vacuum", "380,0,0\n800,1,2\n", "nk.csv:1:5: error: n: n = k = 0"},
        CsvCase{"Infinite", "380,1,2\n800,inf,2\n", "is not a finite number"},
        CsvCase{"NarrowRange", "400,1,2\n700,1,2\n",
                "nk.csv: error: wavelength_nm: covers 400-700 nm; data must span at least "
                "380-780 nm"}),
    [](const testing::TestParamInfo<CsvCase>& param) { return param.param.name; });

TEST(NkCsv, AcceptsCommentsHeaderAndCrLf) {
  const std::string text = "# measured\r\nwavelength_nm, n, k\r\n380,1.5,2\r\n\r\n780,1.25,3\r\n";
  Diagnostics diagnostics;
  const auto spectrum = parse_nk_csv(text, TextLocator("nk.csv", text), diagnostics);
  ASSERT_TRUE(spectrum.has_value());
  EXPECT_EQ(spectrum->wavelength_nm.size(), 2u);
  EXPECT_DOUBLE_EQ(spectrum->at(580.0).n, 1.375);
  EXPECT_DOUBLE_EQ(spectrum->at(100.0).k, 2.0);  // held constant beyond the data
}

}  // namespace
}  // namespace matc
