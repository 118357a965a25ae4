// The LUT options shared by `matc lut`, `matc --lut` (batch) and `matc eval`.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "matc/emit/build.h"
#include "matc/lut/lut_files.h"

namespace matc::cli {

struct LutCliOptions {
  LutOptions bake;
  LutPrecision precision = LutPrecision::f32;
  runtime::BasisKind basis = runtime::kDefaultBasis;  // the table integrates it
  // The coefficient table's texels (docs/coefficient-table.md): f16 costs it nothing measurable.
  LutPrecision coefficient_table_precision = LutPrecision::f16;
};

// Adds --basis to `app`: which shipped basis the coefficients and tables use.
void add_basis_option(CLI::App& app, runtime::BasisKind& basis);

// Adds --<prefix>size, --<prefix>samples, --<prefix>precision and --basis to `app`.
void add_lut_options(CLI::App& app, LutCliOptions& options, const std::string& prefix);

// Adds --coefficient-table-precision to `app` (the commands that build shaders).
void add_coefficient_table_option(CLI::App& app, LutCliOptions& options);

// The table and embedded-table settings of a build, shared by `matc` and `matc validate`.
BuildOptions table_build_options(const LutCliOptions& lut, bool embed_lut,
                                 std::size_t embed_lut_size);

}  // namespace matc::cli
