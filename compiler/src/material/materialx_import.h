// Importing metals from MaterialX documents (1.36-1.39): Autodesk Standard Surface and OpenPBR
// Surface shaders become matc materials (docs/interchange.md).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostics.h"
#include "material/document_import.h"
#include "material/material.h"
#include "material/parse.h"

namespace matc {

inline constexpr std::uintmax_t kMaxMaterialXFileBytes = 16u << 20;  // 16 MiB
// Top-level elements read at most: a larger document is refused before anything is imported.
inline constexpr std::size_t kMaxMaterialXElements = 100000;

using MaterialXImport = DocumentImport;

// Imports every metallic surface material of the document `text`; `path` names it in diagnostics.
MaterialXImport import_materialx(std::string_view text, const std::string& path);

// Whether `path` names a MaterialX document (".mtlx", any case).
bool is_materialx_path(std::string_view path);

// `name` made to follow matc's name rule (kMaterialNameRule): other characters become '_', runs
// of '_' one, a name that does not start with a letter gets "m_" before it, at most 64 characters;
// a name the shared library takes ("sum": kNamesTakenByLibrary) gets "_material" after it.
std::string sanitized_material_name(std::string_view name);

}  // namespace matc
