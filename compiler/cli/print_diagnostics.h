#pragma once

#include "matc/diagnostics.h"

namespace matc::cli {

// Writes each diagnostic on its own line to standard error.
void print_diagnostics(const Diagnostics& diagnostics);

}  // namespace matc::cli
