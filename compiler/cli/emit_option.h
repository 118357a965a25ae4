// --emit, as the compile and `matc layout` take it: a comma-separated list of output kinds.
#pragma once

#include <set>
#include <string>

#include <CLI/CLI.hpp>

#include "matc/emit/output_layout.h"

namespace matc::cli {

// Adds --emit to `command`, refusing a kind the output layout does not know.
CLI::Option* add_emit_option(CLI::App& command, std::string& list, const std::string& help);

// The kinds the (checked) list names; every kind when it is empty.
std::set<OutputKind> emitted_kinds(const std::string& list);

}  // namespace matc::cli
