// --emit, as the compile and `matc layout` take it: a comma-separated list of output kinds, by
// the public API's names.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace matc::cli {

// Adds --emit to `command`, refusing a kind the public API does not name; `kinds` stays empty
// (every kind) until the option names some.
CLI::Option* add_emit_option(CLI::App& command, std::vector<std::string>& kinds,
                             const std::string& help);

}  // namespace matc::cli
