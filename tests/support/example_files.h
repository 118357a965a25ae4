// The example material files (examples/materials/*.json) in name order, which several suites
// compile or run matc on. MATC_EXAMPLES_DIR is defined by the suite's CMake target.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace matc::test {

inline std::vector<std::string> example_material_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(MATC_EXAMPLES_DIR))
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace matc::test
