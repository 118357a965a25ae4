// Writing outputs so that a reader (or a killed matc) only ever sees the old or the new file.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace matc {

enum class WriteOutcome { written, unchanged };

// Leaves the file untouched when it already holds `bytes` (so build systems see no change);
// otherwise writes a temporary file beside it and renames it into place.
// Throws std::runtime_error with a readable reason on failure, leaving no temporary behind.
WriteOutcome write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// The same for a file too large to hold in memory: `produce` writes the bytes to the stream it
// is given (the temporary), which is then compared with the existing file piece by piece.
WriteOutcome write_file_atomically(const std::filesystem::path& path,
                                   const std::function<void(std::ostream&)>& produce);

// The canonical form of a path (as far as it exists), for "would this output overwrite an
// input?" checks.
std::string path_identity(const std::filesystem::path& path);

}  // namespace matc
