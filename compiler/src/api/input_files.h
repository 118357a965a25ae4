// The public API's in-memory files (InputFiles, matc/api/material.h) checked and served.
#pragma once

#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "matc/api/material.h"
#include "material/memory_files.h"

namespace matc::api {

// Throws std::invalid_argument naming the first of `files` that could not be a file beside an
// input.
inline void check_input_files(const InputFiles& files) {
  for (const auto& [name, bytes] : files) {
    if (const std::string problem = memory_file_name_problem(name); !problem.empty())
      throw std::invalid_argument(
          fmt::format("files: '{}': {}; a path relative to the input's folder, inside it",
                      echoed(name, 128), problem));
  }
}

}  // namespace matc::api
