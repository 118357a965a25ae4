// A small reader for the numeric CSV files matc consumes (n,k spectra, CIE tables).
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "base/diagnostics.h"

namespace matc {

struct CsvRow {
  std::vector<double> values;
  std::vector<std::size_t> offsets;  // byte offset of each field, for diagnostics
};

// Reads `text` as comma-separated numbers, one row per line. Blank lines and lines starting with
// '#' are skipped. If the first remaining line is not numeric it must equal `header`
// (case-insensitive, spaces ignored). Every row must hold exactly header-many finite numbers.
// Problems are reported to `diagnostics` with positions from `locator`; returns nullopt on error.
std::optional<std::vector<CsvRow>> read_numeric_csv(std::string_view text, std::string_view header,
                                                    const TextLocator& locator,
                                                    Diagnostics& diagnostics);

}  // namespace matc
