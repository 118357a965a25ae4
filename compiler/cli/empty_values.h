// An option given an empty value (`--quad-light ''`, `--material=`) is a usage error: each
// command reads an empty string as "not given", so the value would be dropped without a word.
#pragma once

#include <CLI/CLI.hpp>

namespace matc::cli {

// Adds the check to every option that takes a value, in `app` and all its subcommands.
void refuse_empty_values(CLI::App& app);

}  // namespace matc::cli
