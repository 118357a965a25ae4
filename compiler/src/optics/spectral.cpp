#include "optics/spectral.h"

#include <array>
#include <stdexcept>

#include "base/csv_table.h"
#include "base/embedded_data.h"

namespace matc {
namespace {

constexpr std::size_t kGridSize = kCieLastNm - kCieFirstNm + 1;

// Reads an embedded CIE table into a map from integer wavelength to its columns.
std::vector<CsvRow> read_cie_table(std::string_view path, std::string_view header) {
  const std::string_view text = embedded_data::file(path);
  Diagnostics diagnostics;
  auto rows = read_numeric_csv(text, header, TextLocator(std::string(path), text), diagnostics);
  if (!rows) throw std::logic_error("embedded CIE table is malformed: " + std::string(path));
  return std::move(*rows);
}

const CsvRow& row_at(const std::vector<CsvRow>& rows, int wavelength) {
  const auto first = static_cast<int>(rows.front().values[0]);
  const auto& row = rows.at(static_cast<std::size_t>(wavelength - first));
  if (static_cast<int>(row.values[0]) != wavelength) {
    throw std::logic_error("embedded CIE table is not on a 1 nm grid");
  }
  return row;
}

// w_c(lambda) on the integration grid for one working space, each channel summing to 1. The
// tabulated D65 white (x, y = 0.31271, 0.32902) is adapted with Bradford to the space's white, so
// a perfect mirror is exactly the space's white and converting between spaces afterwards gives
// the same numbers as integrating into the other space (von Kries transforms compose).
std::vector<Rgb> weights_for(ColorSpace space) {
  const auto cmf = read_cie_table("cie/cie1931_2deg.csv", "wavelength_nm,x_bar,y_bar,z_bar");
  const auto d65 = read_cie_table("cie/d65.csv", "wavelength_nm,relative_power");
  std::vector<Xyz> lit(kGridSize);
  Xyz white{};
  for (std::size_t i = 0; i < kGridSize; ++i) {
    const int wavelength = kCieFirstNm + static_cast<int>(i);
    const auto& xyz = row_at(cmf, wavelength).values;
    const double illuminant = row_at(d65, wavelength).values[1];
    for (std::size_t c = 0; c < 3; ++c) {
      lit[i][c] = illuminant * xyz[c + 1];
      white[c] += lit[i][c];
    }
  }
  const Xyz space_white = xyz_from_chromaticity(color_space_definition(space).white);
  const Matrix3 to_rgb =
      multiply(inverse(rgb_to_xyz(space)),
               bradford_adaptation({white[0] / white[1], 1.0, white[2] / white[1]}, space_white));
  std::vector<Rgb> w(kGridSize);
  Rgb total{};
  for (std::size_t i = 0; i < kGridSize; ++i) {
    w[i] = multiply(to_rgb, lit[i]);
    for (std::size_t c = 0; c < 3; ++c)
      total[c] += w[i][c];
  }
  for (auto& wi : w) {
    for (std::size_t c = 0; c < 3; ++c)
      wi[c] /= total[c];
  }
  return w;
}

}  // namespace

const std::vector<Rgb>& spectral_weights(ColorSpace space) {
  static const std::array<std::vector<Rgb>, 4> all = {
      weights_for(ColorSpace::lin_rec709), weights_for(ColorSpace::acescg),
      weights_for(ColorSpace::lin_rec2020), weights_for(ColorSpace::lin_displayp3)};
  return all.at(static_cast<std::size_t>(space));
}

SpectralCurve::SpectralCurve(const Spectrum& spectrum, ColorSpace space)
    : weights_(spectral_weights(space)) {
  ior_.reserve(kGridSize);
  for (std::size_t i = 0; i < kGridSize; ++i) {
    ior_.push_back(spectrum.at(static_cast<double>(kCieFirstNm) + static_cast<double>(i)));
  }
}

Rgb SpectralCurve::at(double mu) const {
  Rgb result{};
  for (std::size_t i = 0; i < kGridSize; ++i) {
    // The real-arithmetic form: equal to fresnel_exact within 1e-10 (tests/unit/bake/bake_test.cpp)
    // and several times faster, which is most of compiling a spectral material.
    const double f = fresnel_conductor(mu, ior_[i]);
    for (std::size_t c = 0; c < 3; ++c)
      result[c] += weights_[i][c] * f;
  }
  return result;
}

}  // namespace matc
