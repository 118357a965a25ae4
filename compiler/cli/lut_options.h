// The LUT options shared by `matc lut`, `matc --lut` (batch) and `matc eval`.
#pragma once

#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "matc/lut/lut_files.h"

namespace matc::cli {

struct LutCliOptions {
  LutOptions bake;
  std::string precision = "f32";
};

// Adds --<prefix>size, --<prefix>samples and --<prefix>precision to `app`.
void add_lut_options(CLI::App& app, LutCliOptions& options, const std::string& prefix);

LutPrecision precision_of(const LutCliOptions& options);

// Writes `path` and its manifest `path + ".json"` atomically; returns how many files changed.
// Throws std::runtime_error on failure.
std::size_t write_lut_files(const std::filesystem::path& path, const BakedLut& baked,
                            LutFormat format, LutPrecision precision);

}  // namespace matc::cli
