// The matc commands. Each command's file registers its options and help on the command line
// (register_X beside its run_X) and main walks the list; each run returns the process exit code
// (kExit* below).
#pragma once

#include <functional>
#include <vector>

#include <CLI/CLI.hpp>

namespace matc::cli {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitInputError = 1;  // a material or data file is invalid
inline constexpr int kExitUsageError = 2;  // the command line is invalid
inline constexpr int kExitInternalError = 3;
inline constexpr int kExitValidationFailed = 4;  // device results differ from the CPU runtime's
inline constexpr int kExitNoDevice = 5;          // no usable Vulkan driver or device

// A command as main sees it: its node in the command line and what runs it once that node is
// parsed (the options it reads live in the closure).
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
  bool reads_inputs = false;  // reports problems in inputs: takes --diagnostics-format
};

// The compile, matc's default command: its options go on `app` itself.
Command register_compile(CLI::App& app);
Command register_eval(CLI::App& app);
Command register_validate(CLI::App& app);
// `matc basis` and, first, its subcommands that regenerate checked-in sources.
std::vector<Command> register_basis(CLI::App& app);
Command register_lut(CLI::App& app);
Command register_bake(CLI::App& app);
Command register_report(CLI::App& app);
Command register_import(CLI::App& app);
Command register_gltf(CLI::App& app);
Command register_layout(CLI::App& app);

}  // namespace matc::cli
