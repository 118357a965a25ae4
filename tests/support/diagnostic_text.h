// Every diagnostic as the CLI prints it, one per line: what the tests search for a message in.
#pragma once

#include <string>

#include "base/diagnostics.h"

namespace matc::test {

inline std::string diagnostic_text(const Diagnostics& diagnostics) {
  std::string text;
  for (const Diagnostic& d : diagnostics.items())
    text += format_diagnostic(d) + "\n";
  return text;
}

}  // namespace matc::test
