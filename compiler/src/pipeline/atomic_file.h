// Writing outputs so that a reader (or a killed matc) only ever sees the old or the new file.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/output_file.h"

namespace matc {

enum class WriteOutcome { written, unchanged };

// Leaves the file untouched when it already holds `bytes` (so build systems see no change);
// otherwise writes a file beside it that has no name until it is complete (base/pending_file.h)
// and gives it the output's name. Throws std::runtime_error with a readable reason on failure,
// leaving no temporary behind.
WriteOutcome write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// The same for a file too large to hold in memory: `produce` writes the bytes to the stream it
// is given (the temporary), which is then compared with the existing file piece by piece.
WriteOutcome write_file_atomically(const std::filesystem::path& path,
                                   const std::function<void(std::ostream&)>& produce);

// All of `files` into `directory`, or none: every changed file is written (and every target
// checked to be replaceable) before the first takes its name, so a failure leaves the directory as
// it was. Outcomes in the order of `files`.
std::vector<WriteOutcome> write_files_atomically(const std::filesystem::path& directory,
                                                 std::span<const OutputFile> files);

// Whether the regular file `a` and the file at `b` hold the same bytes, read a block at a time (a
// symlink at `b` never does: it is not read).
bool same_file_contents(const std::filesystem::path& a, const std::filesystem::path& b);

// The canonical form of a path (as far as it exists), for "would this output overwrite an
// input?" checks.
std::string path_identity(const std::filesystem::path& path);

}  // namespace matc
