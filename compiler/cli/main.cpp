// matc: compiles material files into Fresnel coefficients (and, later, shaders and LUTs).
#include <cstdio>
#include <exception>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "commands.h"
#include "matc/version.h"

int main(int argc, char** argv) {
  using namespace matc::cli;
  CLI::App app{"matc: compiles materials into an accurate, preintegrable Fresnel decomposition",
               "matc"};
  app.set_version_flag("--version", std::string("matc ") + matc::kVersion);
  app.footer("Exit status: 0 success, 1 invalid input, 2 invalid command line, 3 internal error.");

  CompileOptions compile;
  app.add_option("files", compile.files, "Material files (.json) to compile");
  app.add_option("-o,--output", compile.output_directory,
                 "Directory for <name>.json outputs (created if missing)")
      ->capture_default_str();
  app.add_flag("-k,--keep-going", compile.keep_going,
               "Compile the remaining files after one fails (still exits 1)");
  app.add_flag("-q,--quiet", compile.quiet, "Do not print the summary line");

  EvalOptions eval;
  CLI::App* eval_command =
      app.add_subcommand("eval", "Evaluate a material's decomposed and exact Fresnel as JSON");
  eval_command->add_option("file", eval.file, "Material file")->required();
  eval_command->add_option("--mu", eval.mu, "Cosines of the angle of incidence, comma-separated")
      ->required()
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1.0));

  BasisOptions basis;
  CLI::App* basis_command = app.add_subcommand("basis", "Show the Fresnel basis b_0..b_3");
  basis_command->add_flag("--json", basis.json, "Print {mu, b, probes} as JSON");
  BasisFitOptions basis_fit;
  CLI::App* fit_command = basis_command->add_subcommand(
      "fit", "Refit the basis from its training set and write the C++ table source");
  fit_command->add_option("-o,--output", basis_fit.output,
                          "Where to write (runtime/src/paper_basis_table.cpp); default stdout");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion&) {
    fmt::print("matc {}\n", matc::kVersion);
    return kExitSuccess;
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsageError;
  }

  try {
    if (*eval_command) return run_eval(eval);
    if (*fit_command) return run_basis_fit(basis_fit);
    if (*basis_command) return run_basis(basis);
    if (compile.files.empty()) {
      fmt::print(stderr,
                 "matc: error: no material files given; usage: matc [-o DIR] FILES... "
                 "(see matc --help)\n");
      return kExitUsageError;
    }
    return run_compile(compile);
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc: internal error: {}\n", error.what());
    return kExitInternalError;
  }
}
