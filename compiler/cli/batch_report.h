// What the batch commands (the compile, `matc bake`, `matc import`) share around their work: the
// check that no output overwrites an input, the dependency file, and the summary line.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "atomic_file.h"

namespace matc::cli {

// The inputs that lie in the output directory (the only ones an output can overwrite), by file
// name, so that a batch of 100,000 keeps no more than those.
class InputsInOutputDirectory {
 public:
  explicit InputsInOutputDirectory(const std::filesystem::path& output_directory);
  // `as_given` is how the user named it (what the error quotes); `path` where it lies.
  void add(const std::filesystem::path& path, const std::string& as_given);
  // "output 'DIR/x.json' would overwrite the input x.json" for the first of `outputs` that would.
  std::optional<std::string> overwrite_problem(
      const std::vector<std::filesystem::path>& outputs) const;

 private:
  // The input (as given) that writing `output`, a file in the output directory, would replace.
  std::optional<std::string> overwritten_by(const std::filesystem::path& output) const;

  std::filesystem::path directory_identity_;
  std::map<std::string, std::string> inputs_;  // file name -> as given
};

// "an output directory (-o) that holds no input file": what the overwrite error asks for.
inline constexpr const char* kOutputDirectoryRule =
    "an output directory (-o) that holds no input file";

// The counts a batch ends with.
struct BatchCounts {
  std::size_t done = 0;  // materials compiled, assets baked, materials imported
  std::size_t written = 0;
  std::size_t unchanged = 0;
  std::size_t failed = 0;
  std::size_t not_attempted = 0;

  void count(WriteOutcome outcome) { ++(outcome == WriteOutcome::written ? written : unchanged); }
};

// How a command names its summary: "matc bake: 3 baked (...)".
struct BatchSummaryWords {
  const char* command;  // "matc", "matc bake", "matc import"
  const char* done;     // "compiled", "baked", "imported": also the JSON key
};

// One line on standard error (or one JSON object when diagnostics are JSON), unless `quiet`.
// `seconds`, when given, is how long the batch took.
void print_batch_summary(const BatchSummaryWords& words, const BatchCounts& counts, bool quiet,
                         std::optional<double> seconds = std::nullopt);

// -k,--keep-going and -q,--quiet, with what keeping going does and what quiet silences.
void add_keep_going_and_quiet(CLI::App& command, bool& keep_going, bool& quiet,
                              const std::string& keep_going_does, const std::string& silenced);

// --depfile FILE and --MD (DIR/`default_name`); `dependencies` says what the file lists.
void add_depfile_options(CLI::App& command, std::string& depfile, bool& write_depfile,
                         const std::string& dependencies, const std::string& default_name);

// --depfile FILE, or -MD's DIR/`default_name`, or none (empty).
std::filesystem::path depfile_path(const std::string& depfile_option, bool write_depfile,
                                   const std::filesystem::path& output_directory,
                                   const std::string& default_name);

// Writes the dependency file (the matc binary added to `dependencies`); on failure prints the
// reason and returns false.
bool write_depfile(const std::filesystem::path& path,
                   const std::vector<std::filesystem::path>& targets,
                   std::vector<std::filesystem::path> dependencies);

}  // namespace matc::cli
