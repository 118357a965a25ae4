// Reading and validating material files (format: docs/material-format.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "base/diagnostics.h"
#include "material/material.h"

namespace matc {

inline constexpr std::uintmax_t kMaxMaterialFileBytes = 1u << 20;   // 1 MiB
inline constexpr std::uintmax_t kMaxSpectrumFileBytes = 16u << 20;  // 16 MiB
inline constexpr std::size_t kMaxMaterialNameLength = 64;

// The bytes of a file, or the reason they could not be read.
struct LoadedFile {
  std::optional<std::string> bytes;
  std::string error;
};

// Reads a regular file of at most `max_bytes`; directories, missing files and larger files fail
// with a reason instead of being read.
LoadedFile load_file(const std::filesystem::path& path, std::uintmax_t max_bytes);

// How matc reaches material files and the files they reference (spectral CSVs). The default,
// load_file, reads the file system; an asset tool can serve files from memory instead.
using FileLoader = std::function<LoadedFile(const std::filesystem::path&, std::uintmax_t)>;

struct ParseResult {
  std::optional<Material> material;  // set when there is no error (warnings may remain)
  Diagnostics diagnostics;
};

// Parses material JSON `text`; `path` names it in diagnostics, and relative spectral files are
// resolved against its folder.
ParseResult parse_material(std::string_view text, const std::string& path,
                           const FileLoader& loader = load_file);

// Reads and parses a material file.
ParseResult read_material_file(const std::string& path, const FileLoader& loader = load_file);

// What material_name_problem accepts, as diagnostics word it (bake assets follow the same rule:
// names become file stems and generated identifiers).
inline constexpr std::string_view kMaterialNameRule =
    "a name matching [A-Za-z][A-Za-z0-9_]*, at most 64 characters, without '__', and none of "
    "the shared library's (f82, sum, preintegrated, from_f0, ...: docs/material-format.md)";

// Why `name` is not a valid material name, or nullopt if it is.
std::optional<std::string> material_name_problem(std::string_view name);

// Names name files, and file systems may ignore case: two names clash when their keys (the name
// in lower case) are equal.
std::string material_name_key(std::string_view name);

}  // namespace matc
