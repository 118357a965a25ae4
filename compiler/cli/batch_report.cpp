#include "batch_report.h"

#include <cstdio>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "print_diagnostics.h"

namespace matc::cli {

namespace fs = std::filesystem;

void print_batch_summary(const BatchSummaryWords& words, const api::BatchResult& counts, bool quiet,
                         std::optional<double> seconds) {
  if (quiet) return;
  if (diagnostics_format() == DiagnosticsFormat::json) {
    // Standard error stays JSON Lines for tools: the summary is one more object.
    nlohmann::ordered_json summary = {{words.done, counts.compiled},
                                      {"written", counts.written},
                                      {"unchanged", counts.unchanged},
                                      {"failed", counts.failed},
                                      {"not_attempted", counts.not_attempted}};
    if (seconds) summary["seconds"] = *seconds;
    fmt::print(stderr, "{}\n", nlohmann::ordered_json{{"summary", summary}}.dump());
    return;
  }
  fmt::print(stderr, "{}: {} {} ({} files written, {} unchanged), {} failed{}{}\n", words.command,
             counts.compiled, words.done, counts.written, counts.unchanged, counts.failed,
             counts.not_attempted > 0
                 ? fmt::format(", {} not attempted (use --keep-going)", counts.not_attempted)
                 : "",
             seconds ? fmt::format(" in {:.2f} s", *seconds) : "");
}

void add_keep_going_and_quiet(CLI::App& command, bool& keep_going, bool& quiet,
                              const std::string& keep_going_does, const std::string& silenced) {
  command.add_flag("-k,--keep-going", keep_going, keep_going_does + " (still exits 1)");
  command.add_flag("-q,--quiet", quiet, "Do not print the " + silenced);
}

void add_depfile_options(CLI::App& command, std::string& depfile, bool& write_depfile,
                         const std::string& dependencies, const std::string& default_name) {
  command.add_option("--depfile", depfile,
                     "Write the outputs' dependencies (" + dependencies +
                         ") to FILE in the Makefile syntax Ninja and CMake read");
  command.add_flag("--MD", write_depfile,
                   "The same, as DIR/" + default_name + " (also spelled -MD)");
}

std::vector<std::string> matc_binary_dependency() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  return {self.string()};
}

std::string depfile_path(const std::string& depfile_option, bool write_depfile,
                         const std::string& output_directory, const std::string& default_name) {
  if (!depfile_option.empty()) return depfile_option;
  return write_depfile ? (fs::path(output_directory) / default_name).string() : std::string();
}

}  // namespace matc::cli
