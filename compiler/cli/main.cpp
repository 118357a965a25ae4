// matc: compiles material files into Fresnel coefficients, shaders, SPIR-V, headers and the LUT.
// Each command registers itself (commands.h); main parses the command line and runs the one given.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "commands.h"
#include "empty_values.h"
#include "interrupt_cleanup.h"
#include "matc/api/diagnostics.h"
#include "matc/version.h"
#include "print_diagnostics.h"

int main(int argc, char** argv) {
  using namespace matc::cli;
  remove_temporaries_when_interrupted();
  CLI::App app{"matc: compiles materials into an accurate, preintegrable Fresnel decomposition",
               "matc"};
  app.set_version_flag("--version", std::string("matc ") + matc::kVersion);
  app.footer(
      "Exit status: 0 success, 1 invalid input, 2 invalid command line, 3 internal error, "
      "4 shaders differ from the CPU runtime on the device, 5 no usable Vulkan device.");

  // In the order they are tried once parsed: a subcommand before its parent, the compile (the
  // command line itself, always parsed) last.
  std::vector<Command> commands = {register_eval(app), register_validate(app)};
  for (Command& command : register_basis(app))
    commands.push_back(std::move(command));
  for (Command (*add)(CLI::App&) : {register_lut, register_bake, register_report, register_import,
                                    register_gltf, register_layout, register_compile})
    commands.push_back(add(app));

  std::string diagnostics_format = "text";
  for (const Command& command : commands) {
    if (!command.reads_inputs) continue;
    command.app
        ->add_option("--diagnostics-format", diagnostics_format,
                     "How problems in inputs are reported on standard error: text "
                     "(file:line:col: error: ...) or json (one object per line)")
        ->check(CLI::IsMember({"text", "json"}));
  }

  refuse_empty_values(app);

  // -MD, as compilers spell it: CLI11 only takes one-letter names after a single dash.
  std::vector<std::string> arguments(argv + 1, argv + argc);
  std::replace(arguments.begin(), arguments.end(), std::string("-MD"), std::string("--MD"));
  std::reverse(arguments.begin(), arguments.end());  // CLI11's order for a vector
  try {
    app.parse(arguments);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion&) {
    fmt::print("matc {}\n", matc::kVersion);
    return kExitSuccess;
  } catch (const CLI::ParseError& e) {
    // CLI11's message may quote an argument: escaped, as every echoed input is.
    fmt::print(stderr, "{}\nRun with --help for more information.\n",
               matc::api::printable(e.what()));
    return kExitUsageError;
  }

  set_diagnostics_format(diagnostics_format == "json" ? DiagnosticsFormat::json
                                                      : DiagnosticsFormat::text);
  try {
    for (const Command& command : commands)
      if (*command.app) return command.run();
    return kExitInternalError;  // unreachable: the compile's node is the parsed command line
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc: internal error: {}\n", error.what());
    return kExitInternalError;
  }
}
