#include "pipeline/import_batch.h"

#include <filesystem>
#include <optional>
#include <vector>

#include "batch_reporter.h"
#include "material/document_import.h"
#include "pipeline/inputs_in_output_directory.h"
#include "pipeline/unique_names.h"

namespace matc {

namespace fs = std::filesystem;

BatchCounts import_batch(std::span<const MaterialSource> documents, OutputSink& output,
                         const ImportBatchOptions& options, const BatchEvents& events) {
  const fs::path* directory = output.directory();
  std::optional<InputsInOutputDirectory> inputs;
  if (directory) {
    inputs.emplace(*directory);
    for (const MaterialSource& document : documents)
      if (!document.text) inputs->add(document.path, document.path);
  }
  const auto file_name = [](const ImportedMaterial& material) {
    return material.material.name + ".json";
  };
  std::vector<DocumentImport> imports;
  UniqueNames names;
  BatchCounts counts;
  for (const MaterialSource& document : documents) {
    DocumentImport imported;
    if (!is_document_path(document.path)) {
      imported.diagnostics.error({document.path, 0, 0}, "",
                                 "is not a MaterialX document or a glTF asset",
                                 "a .mtlx, .gltf or .glb file");
    } else {
      imported = document.text ? import_document(*document.text, document.path)
                               : read_document_file(document.path);
    }
    for (const ImportedMaterial& material : imported.materials) {
      const std::optional<std::string> problem =
          inputs ? inputs->overwrite_problem({*directory / file_name(material)}) : std::nullopt;
      if (problem) {
        imported.diagnostics.error(material.material.name_location, "name", *problem,
                                   kOutputDirectoryRule);
      } else {
        names.claim(material.material, "an import", imported.diagnostics);
      }
    }
    if (imported.diagnostics.has_errors()) ++counts.failed;
    imports.push_back(std::move(imported));
  }
  const bool stop = counts.failed > 0 && !options.keep_going;
  const std::string where = output_name(output).string();
  BatchReporter reporter(events);
  for (const DocumentImport& imported : imports) {
    reporter.diagnostics(imported.diagnostics);
    if (imported.diagnostics.has_errors()) continue;
    if (stop) {
      counts.not_attempted += imported.materials.size();
      continue;
    }
    try {
      for (const ImportedMaterial& material : imported.materials) {
        counts.count(output.write(file_name(material), material.json));
        ++counts.done;
      }
    } catch (const std::exception& error) {
      reporter.error(where, error.what());
      ++counts.failed;
    }
  }
  return counts;
}

}  // namespace matc
