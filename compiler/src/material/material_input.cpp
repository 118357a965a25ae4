#include "material/material_input.h"

#include <utility>

#include "material/document_import.h"
#include "material/parse.h"

namespace matc {
namespace {

MaterialInput from_document(DocumentImport imported) {
  MaterialInput input;
  input.diagnostics = std::move(imported.diagnostics);
  for (ImportedMaterial& material : imported.materials)
    input.materials.push_back(std::move(material.material));
  if (input.diagnostics.has_errors()) input.materials.clear();
  return input;
}

MaterialInput from_material(ParseResult parsed) {
  MaterialInput input;
  input.diagnostics = std::move(parsed.diagnostics);
  if (parsed.material && !input.diagnostics.has_errors())
    input.materials.push_back(std::move(*parsed.material));
  return input;
}

}  // namespace

MaterialInput read_material_input(const std::string& path) {
  if (is_document_path(path)) return from_document(read_document_file(path));
  return from_material(read_material_file(path));
}

MaterialInput parse_material_input(std::string_view text, const std::string& path,
                                   const FileLoader& loader) {
  if (is_document_path(path)) return from_document(import_document(text, path, loader));
  return from_material(parse_material(text, path, loader));
}

}  // namespace matc
