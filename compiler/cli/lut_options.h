// The LUT options shared by `matc lut`, `matc --lut` (batch) and `matc eval`.
#pragma once

#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "matc/emit/build.h"
#include "matc/lut/lut_files.h"

namespace matc::cli {

struct LutCliOptions {
  LutOptions bake;
  std::string precision = "f32";
  std::string basis{runtime::basis_name(runtime::kDefaultBasis)};  // the table integrates it
  // The coefficient table's texels (docs/coefficient-table.md): f16 costs it nothing measurable.
  std::string coefficient_table_precision = "f16";
};

// Adds --basis to `app`: which shipped basis the coefficients and tables use.
void add_basis_option(CLI::App& app, std::string& basis);

// Adds --<prefix>size, --<prefix>samples, --<prefix>precision and --basis to `app`.
void add_lut_options(CLI::App& app, LutCliOptions& options, const std::string& prefix);

// Adds --coefficient-table-precision to `app` (the commands that build shaders).
void add_coefficient_table_option(CLI::App& app, LutCliOptions& options);

LutPrecision precision_of(const LutCliOptions& options);
LutPrecision coefficient_table_precision_of(const LutCliOptions& options);
runtime::BasisKind basis_of(const std::string& basis);

// The table and embedded-table settings of a build, shared by `matc` and `matc validate`.
BuildOptions table_build_options(const LutCliOptions& lut, bool embed_lut,
                                 std::size_t embed_lut_size);

struct LutWriteCounts {
  std::size_t written = 0;
  std::size_t unchanged = 0;  // already held the same bytes, left untouched
};

// Writes `path` and its manifest `path + ".json"` atomically.
// Throws std::runtime_error on failure.
LutWriteCounts write_lut_files(const std::filesystem::path& path, const BakedLut& baked,
                               LutFormat format, LutPrecision precision);

}  // namespace matc::cli
