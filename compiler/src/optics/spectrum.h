// Measured complex IOR as a function of vacuum wavelength, and its reader.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "base/diagnostics.h"
#include "optics/fresnel.h"

namespace matc {

// Spectral data must span at least the visible range the CIE weights are significant over.
inline constexpr double kSpectrumRequiredFirstNm = 380.0;
inline constexpr double kSpectrumRequiredLastNm = 780.0;
// Upper bound accepted for n and k; real metals in the visible stay far below it.
inline constexpr double kMaxIorComponent = 1000.0;

struct Spectrum {
  std::vector<double> wavelength_nm;  // strictly increasing
  std::vector<double> n;
  std::vector<double> k;

  // Linear interpolation in wavelength, held constant beyond the first and last samples.
  ComplexIor at(double wavelength_nm) const;
};

// Parses a `wavelength_nm,n,k` CSV (header optional, '#' comments allowed) and checks it: strictly
// increasing wavelengths, 0 <= n, k <= kMaxIorComponent, not n = k = 0, covering 380-780 nm.
std::optional<Spectrum> parse_nk_csv(std::string_view text, const TextLocator& locator,
                                     Diagnostics& diagnostics);

}  // namespace matc
