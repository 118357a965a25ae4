// --color-space and --gamut-mapping, shared by the commands that compile materials.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "matc/compile.h"

namespace matc::cli {

struct ColorCliOptions {
  std::string space{color_space_name(kDefaultColorSpace)};
  std::string gamut_mapping{gamut_mapping_name(GamutMapping::none)};
};

void add_color_options(CLI::App& app, ColorCliOptions& options);

// The validated options (CLI11 has checked the names).
ColorOptions color_options_of(const ColorCliOptions& options);

}  // namespace matc::cli
