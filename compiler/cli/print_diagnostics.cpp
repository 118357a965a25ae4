#include "print_diagnostics.h"

#include <cstdio>

#include <fmt/core.h>

namespace matc::cli {

void print_diagnostics(const Diagnostics& diagnostics) {
  for (const Diagnostic& diagnostic : diagnostics.items()) {
    fmt::print(stderr, "{}\n", format_diagnostic(diagnostic));
  }
}

}  // namespace matc::cli
