// Files an input names (a spectral CSV, a glTF's buffers) held in memory instead of on disk: what
// a face without a file system (the WebAssembly package) or an asset tool hands the readers.
#pragma once

#include <map>
#include <string>

#include "matc/material/parse.h"

namespace matc {

// Relative path (to the input's folder, as the input names it: "spectra/gold.csv") -> bytes.
using MemoryFiles = std::map<std::string, std::string>;

// Why `name` cannot name a file beside an input (empty, absolute, with a NUL, a backslash, a
// drive or scheme, or climbing out of the folder), or empty when it can.
std::string memory_file_name_problem(const std::string& name);

// A loader that serves `files` for an input named `input_path`: a path the readers resolve
// against the input's folder is looked up by its part below that folder (normalised); any other
// path, or one not among `files`, cannot be read. `files` must outlive the loader; its names must
// pass memory_file_name_problem.
FileLoader memory_file_loader(const MemoryFiles& files, const std::string& input_path);

}  // namespace matc
