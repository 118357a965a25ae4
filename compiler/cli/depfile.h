// Make-syntax dependency files, as Ninja (`depfile =`) and CMake (`DEPFILE`) read them: what a
// build wrote depends on which inputs, so the build system reruns matc when one changes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace matc::cli {

// "t1 t2: d1 d2\n" with absolute paths; spaces, '#' and '$' escaped the way Ninja unescapes them.
std::string depfile_text(const std::vector<std::filesystem::path>& targets,
                         const std::vector<std::filesystem::path>& dependencies);

// The running matc binary: its templates, presets and version are part of every output.
std::filesystem::path matc_executable();

}  // namespace matc::cli
