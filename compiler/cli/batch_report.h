// What the batch commands (the compile, `matc bake`, `matc import`) share on the command line:
// -k/-q, the depfile options, and the summary line. The batches themselves are libmatc's
// (pipeline/).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "matc/api/batch.h"

namespace matc::cli {

// How a command names its summary: "matc bake: 3 baked (...)".
struct BatchSummaryWords {
  const char* command;  // "matc", "matc bake", "matc import"
  const char* done;     // "compiled", "baked", "imported": also the JSON key
};

// One line on standard error (or one JSON object when diagnostics are JSON), unless `quiet`.
// `seconds`, when given, is how long the batch took.
void print_batch_summary(const BatchSummaryWords& words, const api::BatchResult& counts, bool quiet,
                         std::optional<double> seconds = std::nullopt);

// -k,--keep-going and -q,--quiet, with what keeping going does and what quiet silences.
void add_keep_going_and_quiet(CLI::App& command, bool& keep_going, bool& quiet,
                              const std::string& keep_going_does, const std::string& silenced);

// --depfile FILE and --MD (DIR/`default_name`); `dependencies` says what the file lists.
void add_depfile_options(CLI::App& command, std::string& depfile, bool& write_depfile,
                         const std::string& dependencies, const std::string& default_name);

// What a depfile lists after a batch's own inputs: the matc binary (its templates, presets and
// version are part of every output), when it can be found.
std::vector<std::string> matc_binary_dependency();

// --depfile FILE, or -MD's DIR/`default_name`, or none (empty).
std::string depfile_path(const std::string& depfile_option, bool write_depfile,
                         const std::string& output_directory, const std::string& default_name);

}  // namespace matc::cli
