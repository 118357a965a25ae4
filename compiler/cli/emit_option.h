// --emit, as the compile and `matc layout` take it: a comma-separated list of output kinds.
#pragma once

#include <set>
#include <string>

#include <CLI/CLI.hpp>

#include "matc/emit/output_layout.h"

namespace matc::cli {

// Adds --emit to `command`, refusing a kind the registry does not name; `kinds` holds every kind
// until the option is given.
CLI::Option* add_emit_option(CLI::App& command, std::set<OutputKind>& kinds,
                             const std::string& help);

}  // namespace matc::cli
