// The materials an input holds: a material file (.json) holds one, a MaterialX document (.mtlx,
// docs/interchange.md) or a glTF asset (.gltf, .glb, docs/gltf.md) any number. One reader, so that
// everything that takes materials (the batch compile, report, validate, eval, an asset tool's
// in-memory sources) takes all of them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostics.h"
#include "material/material.h"
#include "material/parse.h"

namespace matc {

struct MaterialInput {
  std::vector<Material> materials;  // empty when the input has errors
  Diagnostics diagnostics;          // the input's own (and the document's notes), to report
};

// Reads the file at `path`.
MaterialInput read_material_input(const std::string& path);

// Parses `text`, the contents of an input named `path` (its extension says which kind, `.mtlx` a
// MaterialX document; diagnostics name it; relative spectral files and a glTF's buffers resolve
// against its folder and are read through `loader`).
MaterialInput parse_material_input(std::string_view text, const std::string& path,
                                   const FileLoader& loader = load_file);

}  // namespace matc
