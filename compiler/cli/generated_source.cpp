#include "generated_source.h"

#include <cstdio>
#include <exception>

#include <fmt/core.h>

#include "commands.h"
#include "matc/base/echoed_text.h"
#include "matc/pipeline/atomic_file.h"

namespace matc::cli {

int write_generated_source(const std::string& output, const std::string& source) {
  if (output.empty()) {
    fmt::print("{}", source);
    return kExitSuccess;
  }
  try {
    const WriteOutcome outcome = write_file_atomically(output, source);
    fmt::print(stderr, "matc: {} {}\n", outcome == WriteOutcome::written ? "wrote" : "unchanged",
               printable(output));
  } catch (const std::exception& error) {
    fmt::print(stderr, "{}: error: {}\n", printable(output), printable(error.what()));
    return kExitInputError;
  }
  return kExitSuccess;
}

}  // namespace matc::cli
