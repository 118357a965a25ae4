// The table options shared by `matc lut`, the compile and `matc validate`, by the public API's
// names (matc/api/options.h).
#pragma once

#include <cstddef>
#include <string>

#include <CLI/CLI.hpp>

#include "matc/api/build.h"

namespace matc::cli {

struct LutCliOptions {
  std::size_t size = api::kDefaultLutSize;
  std::size_t samples = api::kDefaultLutSamples;
  std::string precision;  // the option's default once registered
  std::string basis;      // the table integrates it
  // The coefficient table's texels (docs/coefficient-table.md): f16 costs it nothing measurable.
  std::string coefficient_table_precision = "f16";
};

// Adds --<prefix>size, --<prefix>samples, --<prefix>precision and --basis to `app`; a build's
// --basis (`per_material_basis`) also takes "auto", a basis per material.
void add_lut_options(CLI::App& app, LutCliOptions& options, const std::string& prefix,
                     bool per_material_basis = false);

// Adds --coefficient-table-precision to `app` (the commands that build shaders).
void add_coefficient_table_option(CLI::App& app, LutCliOptions& options);

// The table and embedded-table settings of a build, shared by `matc` and `matc validate`.
api::BuildOptions table_build_options(const LutCliOptions& lut, bool embed_lut,
                                      std::size_t embed_lut_size);

}  // namespace matc::cli
