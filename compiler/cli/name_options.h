// Options whose value is one of the public API's names (matc/api/options.h), kept as the name:
// CLI11 checks the text against the names and the command passes it to the public API as it is.
#pragma once

#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "matc/matc.h"

namespace matc::cli {

// Adds `flags` to `app`, with `value` the option's default (or `default_name`; shown in help)
// until it is given.
CLI::Option* add_name_option(CLI::App& app, const std::string& flags, std::string& value,
                             std::string_view option, const std::string& help,
                             std::string_view default_name = {});

// --color-space (its aliases taken too) and --gamut-mapping into `options`.
void add_color_name_options(CLI::App& app, api::CompileOptions& options);

}  // namespace matc::cli
