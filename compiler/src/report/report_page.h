// The HTML index of `matc report`: a summary table, then each material's plot and error table.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "compile/compile.h"

namespace matc {

struct ReportEntry {
  std::string name;  // the material's name: its plot is <name>.svg, its samples <name>.csv
  std::string source;
  Rgb f0{};
  FitAccuracy accuracy;
};

// Self-contained (inline style, no external resources). Once the page has loaded, a short script
// sets <body data-plots-loaded="N"> to the number of plots the browser decoded, which is what the
// report test reads back from headless Chromium.
std::string report_index_html(std::span<const ReportEntry> entries, std::string_view basis_name);

}  // namespace matc
