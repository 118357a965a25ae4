// What `matc report` writes (docs/accuracy.md): per material <name>.svg, its curves plotted (the
// exact one, ours, Schlick's, F82-tint's, per channel with their errors), and <name>.csv, the
// samples; and index.html, the error table with every plot. Native builds.
#pragma once

#include <span>
#include <vector>

#include "matc/api/compiled_material.h"
#include "matc/api/files.h"

namespace matc::api {

struct Report {
  std::vector<OutputFile> files;
  std::vector<Diagnostic> diagnostics;  // the compiles' warnings (a poor fit), material by material
};

// The report of `materials`, compiled with `options`. Throws MaterialError when two names differ
// by case alone (they would name the same files on some file systems), std::invalid_argument for
// an option outside its names.
Report report(std::span<const Material> materials, const CompileOptions& options = {});

}  // namespace matc::api
