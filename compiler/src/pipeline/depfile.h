// Make-syntax dependency files, as Ninja (`depfile =`) and CMake (`DEPFILE`) read them: what a
// build wrote depends on which inputs, so the build system reruns matc when one changes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace matc {

// "t1 t2: d1 d2\n" with absolute paths; spaces, '#' and '$' escaped the way Ninja unescapes them;
// each dependency once, in first-seen order.
std::string depfile_text(const std::vector<std::filesystem::path>& targets,
                         const std::vector<std::filesystem::path>& dependencies);

// Writes depfile_text atomically to `path`. Throws std::runtime_error with the reason on failure.
void write_depfile(const std::filesystem::path& path,
                   const std::vector<std::filesystem::path>& targets,
                   const std::vector<std::filesystem::path>& dependencies);

}  // namespace matc
