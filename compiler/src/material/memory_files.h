// Files an input names (a spectral CSV, a glTF's buffers) held in memory instead of on disk: what
// a face without a file system (the WebAssembly package) or an asset tool hands the readers.
#pragma once

#include <map>
#include <string>
#include <string_view>

#include "material/parse.h"

namespace matc {

// Relative path (to the input's folder, as the input names it: "spectra/gold.csv") -> bytes.
using MemoryFiles = std::map<std::string, std::string>;

// Why `path` cannot name a file inside a folder, relative to it: empty, with a NUL byte or a
// backslash, absolute, with a scheme or drive, or climbing out. `what` names it in the message
// ("URI"), `folder` the folder ("the asset's folder"). Empty when it can. The glTF reader's check
// of its URIs and the check of the names below.
std::string relative_file_problem(const std::string& path, std::string_view what,
                                  std::string_view folder);

// Why `name` cannot name a file beside an input (relative_file_problem's reasons, or a folder),
// or empty when it can.
std::string memory_file_name_problem(const std::string& name);

// A loader that serves `files` for an input named `input_path`: a path the readers resolve
// against the input's folder is looked up by its part below that folder (normalised); any other
// path, or one not among `files`, cannot be read. `files` must outlive the loader; its names must
// pass memory_file_name_problem.
FileLoader memory_file_loader(const MemoryFiles& files, const std::string& input_path);

}  // namespace matc
