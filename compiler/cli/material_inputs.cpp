#include "material_inputs.h"

#include <utility>

#include "matc/material/materialx_import.h"
#include "matc/material/parse.h"

namespace matc::cli {

MaterialInput read_material_input(const std::string& path) {
  MaterialInput input;
  if (is_materialx_path(path)) {
    MaterialXImport imported = read_materialx_file(path);
    input.diagnostics = std::move(imported.diagnostics);
    for (ImportedMaterial& material : imported.materials)
      input.materials.push_back(std::move(material.material));
  } else {
    ParseResult parsed = read_material_file(path);
    input.diagnostics = std::move(parsed.diagnostics);
    if (parsed.material) input.materials.push_back(std::move(*parsed.material));
  }
  if (input.diagnostics.has_errors()) input.materials.clear();
  return input;
}

}  // namespace matc::cli
