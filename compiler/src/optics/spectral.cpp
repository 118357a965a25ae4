#include "matc/optics/spectral.h"

#include <array>
#include <stdexcept>

#include "embedded_data.h"
#include "matc/csv_table.h"

namespace matc {
namespace {

constexpr std::size_t kGridSize = kCieLastNm - kCieFirstNm + 1;

// IEC 61966-2-1 (sRGB), XYZ -> linear RGB.
constexpr std::array<std::array<double, 3>, 3> kXyzToLinearSrgb = {{
    {3.2406, -1.5372, -0.4986},
    {-0.9689, 1.8758, 0.0415},
    {0.0557, -0.2040, 1.0570},
}};

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

// w_c(lambda) on the integration grid, each channel summing to 1.
const std::vector<Rgb>& linear_srgb_weights() {
  static const std::vector<Rgb> weights = [] {
    const auto cmf = read_cie_table("cie/cie1931_2deg.csv", "wavelength_nm,x_bar,y_bar,z_bar");
    const auto d65 = read_cie_table("cie/d65.csv", "wavelength_nm,relative_power");
    std::vector<Rgb> w(kGridSize);
    Rgb total{};
    for (std::size_t i = 0; i < kGridSize; ++i) {
      const int wavelength = kCieFirstNm + static_cast<int>(i);
      const auto& xyz = row_at(cmf, wavelength).values;
      const double illuminant = row_at(d65, wavelength).values[1];
      for (std::size_t c = 0; c < 3; ++c) {
        const auto& m = kXyzToLinearSrgb[c];
        w[i][c] = illuminant * (m[0] * xyz[1] + m[1] * xyz[2] + m[2] * xyz[3]);
        total[c] += w[i][c];
      }
    }
    for (auto& wi : w) {
      for (std::size_t c = 0; c < 3; ++c)
        wi[c] /= total[c];
    }
    return w;
  }();
  return weights;
}

}  // namespace

SpectralCurve::SpectralCurve(const Spectrum& spectrum) {
  ior_.reserve(kGridSize);
  for (std::size_t i = 0; i < kGridSize; ++i) {
    ior_.push_back(spectrum.at(static_cast<double>(kCieFirstNm) + static_cast<double>(i)));
  }
}

Rgb SpectralCurve::at(double mu) const {
  const auto& weights = linear_srgb_weights();
  Rgb result{};
  for (std::size_t i = 0; i < kGridSize; ++i) {
    const double f = fresnel_exact(mu, ior_[i]);
    for (std::size_t c = 0; c < 3; ++c)
      result[c] += weights[i][c] * f;
  }
  return result;
}

}  // namespace matc
