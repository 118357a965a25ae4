// --color-space and --gamut-mapping, shared by the commands that compile materials.
#pragma once

#include <CLI/CLI.hpp>

#include "matc/compile/compile.h"

namespace matc::cli {

// Adds both options to `app`; `options` holds the defaults until they are given.
void add_color_options(CLI::App& app, ColorOptions& options);

}  // namespace matc::cli
