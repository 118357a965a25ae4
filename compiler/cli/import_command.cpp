// `matc import`: MaterialX documents to matc material files (docs/interchange.md).
#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/core.h>

#include "atomic_file.h"
#include "batch_report.h"
#include "commands.h"
#include "matc/material/materialx_import.h"
#include "print_diagnostics.h"
#include "unique_names.h"

namespace matc::cli {
namespace {

// `matc import`: MaterialX documents to matc material files.
struct ImportOptions {
  std::vector<std::string> files;
  std::string output_directory = "matc-import";
  bool keep_going = false;
  bool quiet = false;
};

namespace fs = std::filesystem;

int run_import(const ImportOptions& options) {
  // Every document is imported and every name checked before anything is written, so that a
  // failing batch (without --keep-going) writes nothing, and a failing document never does.
  struct Document {
    std::string file;
    MaterialXImport imported;
  };
  std::vector<Document> documents;
  InputsInOutputDirectory inputs(options.output_directory);
  for (const std::string& file : options.files)
    inputs.add(file, file);
  const auto output_of = [&](const ImportedMaterial& material) {
    return fs::path(options.output_directory) / (material.material.name + ".json");
  };
  UniqueNames names;
  BatchCounts counts;  // failures count documents, the rest materials
  for (const std::string& file : options.files) {
    Document document{file, {}};
    if (!is_materialx_path(file)) {
      document.imported.diagnostics.error({file, 0, 0}, "", "is not a MaterialX document",
                                          "a .mtlx file");
    } else {
      document.imported = read_materialx_file(file);
    }
    for (const ImportedMaterial& material : document.imported.materials) {
      const fs::path output = output_of(material);
      if (const auto problem = inputs.overwrite_problem({output})) {
        document.imported.diagnostics.error(material.material.name_location, "name", *problem,
                                            kOutputDirectoryRule);
      } else {
        names.claim(material.material, "an import", document.imported.diagnostics);
      }
    }
    if (document.imported.diagnostics.has_errors()) ++counts.failed;
    documents.push_back(std::move(document));
  }
  const bool stop = counts.failed > 0 && !options.keep_going;
  for (const Document& document : documents) {
    print_diagnostics(document.imported.diagnostics);
    if (document.imported.diagnostics.has_errors()) continue;
    if (stop) {
      counts.not_attempted += document.imported.materials.size();
      continue;
    }
    try {
      fs::create_directories(options.output_directory);
      for (const ImportedMaterial& material : document.imported.materials) {
        counts.count(write_file_atomically(output_of(material), material.json));
        ++counts.done;
      }
    } catch (const std::exception& error) {
      fmt::print(stderr, "{}: error: {}\n", options.output_directory, error.what());
      ++counts.failed;
    }
  }
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
