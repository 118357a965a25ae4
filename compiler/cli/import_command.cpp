// `matc import`: MaterialX documents to matc material files (docs/interchange.md).
#include <string>
#include <vector>

#include "batch_report.h"
#include "commands.h"
#include "matc/api/batch.h"
#include "progress_line.h"

namespace matc::cli {
namespace {

// `matc import`: MaterialX documents to matc material files.
struct ImportOptions {
  std::vector<std::string> files;
  std::string output_directory = "matc-import";
  bool keep_going = false;
  bool quiet = false;
};

int run_import(const ImportOptions& options) {
  std::vector<api::BatchSource> documents;
  for (const std::string& file : options.files)
    documents.push_back(api::BatchSource::file(file));
  ProgressLine no_progress(false);
  const api::BatchResult counts = api::import_batch(
      documents, {options.output_directory, options.keep_going}, printed_events(no_progress));
  print_batch_summary({"matc import", "imported"}, counts, options.quiet);
  return counts.failed > 0 ? kExitInputError : kExitSuccess;
}

}  // namespace

Command register_import(CLI::App& app) {
  auto options = std::make_shared<ImportOptions>();
  CLI::App* command = app.add_subcommand(
      "import",
      "Write a matc material file for each metallic Standard Surface or OpenPBR material of "
      "MaterialX documents (docs/interchange.md)");
  command->add_option("files", options->files, "MaterialX documents (.mtlx)")->required();
  command->add_option("-o,--output", options->output_directory, "Output directory")
      ->capture_default_str();
  add_keep_going_and_quiet(*command, options->keep_going, options->quiet,
                           "Write the other documents' materials when one fails", "summary line");

  return {command, [options] { return run_import(*options); }, true};
}

}  // namespace matc::cli
