// `matc report FILES... -o DIR`: per material an SVG plot and a CSV of its curves, and an HTML
// index with the error tables. All inputs are checked first; with any invalid, nothing is written.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "commands.h"
#include "matc/api/files.h"
#include "matc/api/report.h"
#include "matc/matc.h"
#include "name_options.h"
#include "option_help.h"
#include "print_diagnostics.h"

namespace matc::cli {
namespace {

struct ReportOptions {
  std::vector<std::string> files;
  std::string output_directory = "matc-report";
  api::CompileOptions compile;
};

namespace fs = std::filesystem;

// Every material, or none when any file is invalid (each input's diagnostics printed).
std::optional<std::vector<api::Material>> read_all(const std::vector<std::string>& files) {
  std::vector<api::Material> materials;
  bool ok = true;
  for (const std::string& file : files) {
    try {
      const std::vector<api::Material> read = api::load_materials(file);
      if (!read.empty()) print_diagnostics(read.front().diagnostics());  // the input's, shared
      materials.insert(materials.end(), read.begin(), read.end());
      if (read.empty()) ok = false;
    } catch (const api::MaterialError& error) {
      print_diagnostics(error.diagnostics());
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  return materials;
}

int run_report(const ReportOptions& options) {
  const std::optional<std::vector<api::Material>> materials = read_all(options.files);
  std::optional<api::Report> report;
  if (materials) {
    try {
      report = api::report(*materials, options.compile);
    } catch (const api::MaterialError& error) {  // two names differing by case alone
      print_diagnostics(error.diagnostics());
    }
  }
  if (!report) {
    fmt::print(stderr, "matc report: nothing written: fix the inputs above\n");
    return kExitInputError;
  }
  print_diagnostics(report->diagnostics);

  const fs::path directory(options.output_directory);
  fs::create_directories(directory);
  std::size_t written = 0;
  for (const api::OutputFile& output : report->files) {
    if (api::write_file((directory / output.name).string(), output.bytes) ==
        api::WriteOutcome::written)
      ++written;
  }
  fmt::print(stderr, "matc report: {} materials, {} files written, {} unchanged: {}\n",
             materials->size(), written, report->files.size() - written,
             (directory / "index.html").string());
  return kExitSuccess;
}

}  // namespace

Command register_report(CLI::App& app) {
  auto options = std::make_shared<ReportOptions>();
  CLI::App* command = app.add_subcommand(
      "report",
      "Plot each material's Fresnel curves (exact, ours, Schlick, F82-tint) as SVG, with CSV "
      "samples and an HTML index of the errors");
  command->add_option("files", options->files, "Material files (.json), MaterialX documents")
      ->required();
  command->add_option("-o,--output", options->output_directory, "Output directory")
      ->capture_default_str();
  add_name_option(*command, "--basis", options->compile.basis, "build_basis", kBuildBasisHelp,
                  api::option_default("build_basis"));
  add_color_name_options(*command, options->compile);

  return {command, [options] { return run_report(*options); }, true};
}

}  // namespace matc::cli
