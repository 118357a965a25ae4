// Documents that hold materials in another format than matc's material file: MaterialX
// (materialx_import.h) and glTF (gltf_import.h). Each import hands over the matc material files
// its metals stand for, validated by the same parser as any material file, with the document's
// notes for everything it did not carry; the path's extension says which reader.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "base/diagnostics.h"
#include "material/material.h"
#include "material/parse.h"

namespace matc {

struct ImportedMaterial {
  // Validated as any material file is: source_path is the document, name_location its material
  // element, source_text the material file below.
  Material material;
  std::string json;  // the matc material file it stands for (what `matc import` writes)
  std::size_t document_index = 0;  // its entry in the document (glTF: materials[document_index])
  // glTF: Schlick's curve (no edge colour, no coat) with a baseColorTexture, so its F0 varies per
  // pixel (baseColorFactor times the texture). Schlick's curve is linear in F0, and so are the
  // coefficients: F0 (1, 0, 0, 0) + (1 - F0) times the coefficients at F0 = 0.
  bool per_pixel_f0 = false;
  // glTF: the same texture under an edge colour or a clear coat, which make the curve's shape
  // depend on F0 otherwise: `matc gltf` writes the coefficients at the F0 table's entries
  // (compile/f0_table.h), between which a pixel's are interpolated.
  bool f0_table = false;
};

struct DocumentImport {
  std::vector<ImportedMaterial> materials;  // in document order; empty when there are errors
  Diagnostics diagnostics;  // errors, warnings, and notes for every material skipped
};

// Whether `path` ends in `extension` (given in lower case, with its dot), in any case.
bool path_has_extension(std::string_view path, std::string_view extension);

// Whether `path` names a document an importer reads (.mtlx, .gltf, .glb; any case).
bool is_document_path(std::string_view path);

// Imports the document `bytes` named `path` (its extension says the format; diagnostics name it;
// a glTF's external buffers resolve against its folder through `loader`).
DocumentImport import_document(std::string_view bytes, const std::string& path,
                               const FileLoader& loader = load_file);

// The bytes of the document at `path` (through `loader`, at most its format's size), or nullopt
// with a "cannot read" error in `diagnostics`.
std::optional<std::string> read_document_bytes(const std::string& path, Diagnostics& diagnostics,
                                               const FileLoader& loader = load_file);

// Reads the document at `path` (through `loader`, at most its format's size) and imports it.
DocumentImport read_document_file(const std::string& path, const FileLoader& loader = load_file);

// Adds the material file an import stands for to `result`, validated by the same parser as any
// material file (so a compile of the document and of `matc import`'s file are the same material),
// named at `location` (`field` in diagnostics). A refusal there is an importer's bug, reported as
// one. Bytes that are not UTF-8 in the document's text become U+FFFD in the file.
void add_imported_material(DocumentImport& result, const nlohmann::ordered_json& material_json,
                           const std::string& path, const SourceLocation& location,
                           const std::string& field);

// Names for a document's materials: sanitised (sanitized_material_name) with a note when that
// changes them, and unique ignoring case (they name files), an error on a clash.
class DocumentNames {
 public:
  // The matc name for a material the document names `document_name`, at `location`; `field`
  // names it in diagnostics and `description` in a later clash's message. Empty after an error.
  std::string claim(const std::string& document_name, const SourceLocation& location,
                    const std::string& field, const std::string& description,
                    Diagnostics& diagnostics);
  // The same for a format whose names need not be unique (glTF): a name taken already, one whose
  // generated identifiers a taken name's would define too ('steel', 'preintegrated_steel'), or one
  // of `shared_stems` (the keys of the files every build writes once: matc_lut, ...), becomes
  // `<name>_<n>`, with the smallest n from 2 whose name is free and none of `reserved` (the keys
  // of names the document's later materials hold) or `shared_stems`, with a note saying so.
  std::string claim_unique(const std::string& document_name, const std::set<std::string>& reserved,
                           const std::set<std::string>& shared_stems,
                           const SourceLocation& location, const std::string& field,
                           const std::string& description, Diagnostics& diagnostics);

 private:
  struct First {
    std::string name;  // as imported
    std::string description;
  };
  std::map<std::string, First> taken_;  // name key -> its first use
};

}  // namespace matc
