// The commands that regenerate checked-in sources (`matc basis ...`, `matc layout --generate`)
// write them the same way.
#pragma once

#include <string>

namespace matc::cli {

// The source on standard output (`output` empty), or written atomically to `output` with a line
// saying whether it changed. Returns the exit code.
int write_generated_source(const std::string& output, const std::string& source);

}  // namespace matc::cli
