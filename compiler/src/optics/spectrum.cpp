#include "optics/spectrum.h"

#include <algorithm>

#include <fmt/format.h>

#include "base/csv_table.h"

namespace matc {

ComplexIor Spectrum::at(double wavelength) const {
  if (wavelength <= wavelength_nm.front()) return {n.front(), k.front()};
  if (wavelength >= wavelength_nm.back()) return {n.back(), k.back()};
  const auto upper = std::upper_bound(wavelength_nm.begin(), wavelength_nm.end(), wavelength);
  const auto i = static_cast<std::size_t>(upper - wavelength_nm.begin());
  const double t = (wavelength - wavelength_nm[i - 1]) / (wavelength_nm[i] - wavelength_nm[i - 1]);
  return {n[i - 1] + t * (n[i] - n[i - 1]), k[i - 1] + t * (k[i] - k[i - 1])};
}

std::optional<Spectrum> parse_nk_csv(std::string_view text, const TextLocator& locator,
                                     Diagnostics& diagnostics) {
  const auto rows = read_numeric_csv(text, "wavelength_nm,n,k", locator, diagnostics);
  if (!rows) return std::nullopt;

  const std::string ior_range = fmt::format("0 <= n, k <= {}, not both 0", kMaxIorComponent);
  Spectrum spectrum;
  bool ok = true;
  for (const CsvRow& row : *rows) {
    const double wavelength = row.values[0];
    const double n = row.values[1];
    const double k = row.values[2];
    if (wavelength <= 0.0) {
      diagnostics.error(locator.at(row.offsets[0]), "wavelength_nm",
                        fmt::format("{} is not a positive wavelength", wavelength),
                        "nanometres > 0");
      ok = false;
    } else if (!spectrum.wavelength_nm.empty() && wavelength <= spectrum.wavelength_nm.back()) {
      diagnostics.error(
          locator.at(row.offsets[0]), "wavelength_nm",
          fmt::format("{} does not follow {}", wavelength, spectrum.wavelength_nm.back()),
          "rows sorted by strictly increasing wavelength");
      ok = false;
    }
    if (n < 0.0 || n > kMaxIorComponent) {
      diagnostics.error(locator.at(row.offsets[1]), "n", fmt::format("{} is out of range", n),
                        ior_range);
      ok = false;
    }
    if (k < 0.0 || k > kMaxIorComponent) {
      diagnostics.error(locator.at(row.offsets[2]), "k", fmt::format("{} is out of range", k),
                        ior_range);
      ok = false;
    }
    if (n == 0.0 && k == 0.0) {
      diagnostics.error(locator.at(row.offsets[1]), "n", "n = k = 0 is not a material", ior_range);
      ok = false;
    }
    spectrum.wavelength_nm.push_back(wavelength);
    spectrum.n.push_back(n);
    spectrum.k.push_back(k);
  }
  if (!ok) return std::nullopt;

  if (spectrum.wavelength_nm.front() > kSpectrumRequiredFirstNm ||
      spectrum.wavelength_nm.back() < kSpectrumRequiredLastNm) {
    diagnostics.error(locator.whole_file(), "wavelength_nm",
                      fmt::format("covers {}-{} nm", spectrum.wavelength_nm.front(),
                                  spectrum.wavelength_nm.back()),
                      fmt::format("data must span at least {}-{} nm", kSpectrumRequiredFirstNm,
                                  kSpectrumRequiredLastNm));
    return std::nullopt;
  }
  return spectrum;
}

}  // namespace matc
