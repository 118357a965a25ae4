// Writing a file as matc writes its outputs (docs/reliability.md): a reader, or a killed process,
// only ever sees the old file or the new one, and a file that already holds the bytes is left
// untouched (build systems see no change). Native builds only.
#pragma once

#include <string>
#include <string_view>

namespace matc::api {

// A file an output of the library is made of, in memory.
struct OutputFile {
  std::string name;  // a plain file name, as matc names it in its output directory
  std::string bytes;
};

enum class WriteOutcome { written, unchanged };

// `bytes` into the file at `path`, through a temporary beside it that is renamed into place.
// Throws std::runtime_error with a readable reason (the path escaped) on failure, leaving no
// temporary behind and nothing else removed.
WriteOutcome write_file(std::string_view path, std::string_view bytes);

// The canonical form of a path (as far as it exists), for "would this output overwrite an input?"
// checks: two paths with the same identity name the same file.
std::string path_identity(std::string_view path);

// Removes the temporaries of every write in progress in this process (this call's and a batch's)
// and refuses new ones, for a face's interrupt handling: call it from an ordinary thread that
// waited for the signal (not from a signal handler), then end the process. Files matc did not
// create are never touched.
void remove_temporaries_in_flight();

}  // namespace matc::api
