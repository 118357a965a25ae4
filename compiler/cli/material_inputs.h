// The materials a command is given: a material file (.json) holds one, a MaterialX document
// (.mtlx, docs/interchange.md) any number. One reader, so that every command that takes materials
// takes both: the batch compile (one job per material), report, validate and eval.
#pragma once

#include <string>
#include <vector>

#include "matc/diagnostics.h"
#include "matc/material/material.h"

namespace matc::cli {

struct MaterialInput {
  std::vector<Material> materials;  // empty when the file has errors
  Diagnostics diagnostics;          // the file's own (and the document's notes), to print
};

MaterialInput read_material_input(const std::string& path);

}  // namespace matc::cli
