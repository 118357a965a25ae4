// `matc import`: MaterialX documents to matc material files (docs/interchange.md).
#include <filesystem>
#include <set>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "atomic_file.h"
#include "commands.h"
#include "matc/material/materialx_import.h"
#include "print_diagnostics.h"
#include "unique_names.h"

namespace matc::cli {

namespace fs = std::filesystem;

int run_import(const ImportOptions& options) {
  // Every document is imported and every name checked before anything is written, so that a
  // failing batch (without --keep-going) writes nothing, and a failing document never does.
  struct Document {
    std::string file;
    MaterialXImport imported;
  };
  std::vector<Document> documents;
  std::set<std::string> input_identities;
  for (const std::string& file : options.files)
    input_identities.insert(path_identity(file));
  const auto output_of = [&](const ImportedMaterial& material) {
    return fs::path(options.output_directory) / (material.material.name + ".json");
  };
  UniqueNames names;
  std::size_t failed = 0;
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
      if (input_identities.contains(path_identity(output))) {
        document.imported.diagnostics.error(
            material.material.name_location, "name",
            fmt::format("output '{}' would overwrite an input", output.string()),
            "an output directory (-o) that holds no input file");
      } else {
        names.claim(material.material, "an import", document.imported.diagnostics);
      }
    }
    if (document.imported.diagnostics.has_errors()) ++failed;
    documents.push_back(std::move(document));
  }
  std::size_t written = 0;
  std::size_t unchanged = 0;
  std::size_t imported = 0;
  for (const Document& document : documents) {
    print_diagnostics(document.imported.diagnostics);
    if (document.imported.diagnostics.has_errors() || (failed > 0 && !options.keep_going)) continue;
    try {
      fs::create_directories(options.output_directory);
      for (const ImportedMaterial& material : document.imported.materials) {
        ++(write_file_atomically(output_of(material), material.json) == WriteOutcome::written
               ? written
               : unchanged);
        ++imported;
      }
    } catch (const std::exception& error) {
      fmt::print(stderr, "{}: error: {}\n", options.output_directory, error.what());
      ++failed;
    }
  }
  if (!options.quiet && diagnostics_format() == DiagnosticsFormat::json) {
    // Standard error stays JSON Lines for tools: the summary is one more object.
    const nlohmann::ordered_json line = {{"summary",
                                          {{"imported", imported},
                                           {"written", written},
                                           {"unchanged", unchanged},
                                           {"failed", failed}}}};
    fmt::print(stderr, "{}\n", line.dump());
  } else if (!options.quiet) {
    fmt::print(stderr,
               "matc import: {} materials imported ({} files written, {} unchanged), {} "
               "documents failed\n",
               imported, written, unchanged, failed);
  }
  return failed > 0 ? kExitInputError : kExitSuccess;
}

}  // namespace matc::cli
