#include "generated_source.h"

#include <cstdio>
#include <exception>

#include <fmt/core.h>

#include "commands.h"
#include "matc/api/diagnostics.h"
#include "matc/api/files.h"

namespace matc::cli {

int write_generated_source(const std::string& output, const std::string& source) {
  if (output.empty()) {
    fmt::print("{}", source);
    return kExitSuccess;
  }
  try {
    const api::WriteOutcome outcome = api::write_file(output, source);
    fmt::print(stderr, "matc: {} {}\n",
               outcome == api::WriteOutcome::written ? "wrote" : "unchanged",
               api::printable(output));
  } catch (const std::exception& error) {
    fmt::print(stderr, "{}: error: {}\n", api::printable(output), api::printable(error.what()));
    return kExitInputError;
  }
  return kExitSuccess;
}

}  // namespace matc::cli
