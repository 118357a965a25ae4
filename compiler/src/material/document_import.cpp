#include "material/document_import.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/identifier_names.h"
#include "material/gltf_import.h"
#include "material/materialx_import.h"

namespace matc {

bool path_has_extension(std::string_view path, std::string_view extension) {
  if (path.size() < extension.size()) return false;
  return std::equal(
      extension.begin(), extension.end(), path.end() - extension.size(),
      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

bool is_gltf_path(std::string_view path) {
  return path_has_extension(path, ".gltf") || path_has_extension(path, ".glb");
}

bool is_document_path(std::string_view path) {
  return is_materialx_path(path) || is_gltf_path(path);
}

DocumentImport import_document(std::string_view bytes, const std::string& path,
                               const FileLoader& loader) {
  if (is_gltf_path(path)) return import_gltf(bytes, path, loader);
  return import_materialx(bytes, path);
}

std::optional<std::string> read_document_bytes(const std::string& path, Diagnostics& diagnostics,
                                               const FileLoader& loader) {
  const bool gltf = is_gltf_path(path);
  LoadedFile loaded = loader(path, gltf ? kMaxGltfFileBytes : kMaxMaterialXFileBytes);
  if (!loaded.bytes) {
    diagnostics.error(
        {path, 0, 0}, "", fmt::format("cannot read: {}", loaded.error),
        gltf ? "a glTF asset of at most 256 MiB" : "a MaterialX document of at most 16 MiB");
  }
  return std::move(loaded.bytes);
}

DocumentImport read_document_file(const std::string& path, const FileLoader& loader) {
  DocumentImport result;
  const std::optional<std::string> bytes = read_document_bytes(path, result.diagnostics, loader);
  if (!bytes) return result;
  return import_document(*bytes, path, loader);
}

void add_imported_material(DocumentImport& result, const nlohmann::ordered_json& material_json,
                           const std::string& path, const SourceLocation& location,
                           const std::string& field) {
  ImportedMaterial imported;
  imported.json =
      material_json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  ParseResult parsed = parse_material(imported.json, path);
  if (!parsed.material) {
    result.diagnostics.error(
        location, field, "the imported material does not validate (an importer bug)",
        parsed.diagnostics.items().empty() ? std::string()
                                           : parsed.diagnostics.items().front().message);
    return;
  }
  imported.material = std::move(*parsed.material);
  imported.material.name_location = location;
  result.materials.push_back(std::move(imported));
}

std::string DocumentNames::claim(const std::string& document_name, const SourceLocation& location,
                                 const std::string& field, const std::string& description,
                                 Diagnostics& diagnostics) {
  const std::string name = sanitized_material_name(document_name);
  if (name != document_name)
    diagnostics.note(location, field, fmt::format("imported as '{}'", name),
                     std::string(kMaterialNameRule));
  const auto [first, inserted] = taken_.emplace(material_name_key(name), First{name, description});
  if (!inserted) {
    diagnostics.error(location, field,
                      fmt::format("becomes '{}', which is '{}' ({}) ignoring case", name,
                                  first->second.name, first->second.description),
                      "material names that still differ after sanitising, ignoring case (they "
                      "name files)");
    return {};
  }
  return name;
}

std::string DocumentNames::claim_unique(const std::string& document_name,
                                        const std::set<std::string>& reserved,
                                        const std::set<std::string>& shared_stems,
                                        const SourceLocation& location, const std::string& field,
                                        const std::string& description, Diagnostics& diagnostics) {
  const std::string name = sanitized_material_name(document_name);
  const std::string name_key = material_name_key(name);
  // A taken key whose names' identifiers `key`'s might meet (ignoring case: a derived name keeps
  // clear of them all).
  const auto neighbour_in = [](const auto& keys, const std::string& key) {
    for (const IdentifierNeighbour& neighbour : identifier_neighbours(key))
      if (keys.contains(neighbour.name)) return true;
    return false;
  };
  const auto taken = taken_.find(name_key);
  // Identifiers keep case: 'steel' meets 'preintegrated_steel', not 'Preintegrated_steel'.
  const IdentifierNeighbour* neighbour = nullptr;
  const std::vector<IdentifierNeighbour> neighbours = identifier_neighbours(name);
  for (const IdentifierNeighbour& candidate : neighbours) {
    const auto other = taken_.find(material_name_key(candidate.name));
    if (!neighbour && other != taken_.end() && other->second.name == candidate.name)
      neighbour = &candidate;
  }
  if (taken == taken_.end() && !neighbour && !shared_stems.contains(name_key))
    return claim(document_name, location, field, description, diagnostics);
  std::string why;
  if (taken != taken_.end()) {
    why = fmt::format("'{}' is '{}' ({}) ignoring case", name, taken->second.name,
                      taken->second.description);
  } else if (neighbour) {
    const First& other = taken_.at(material_name_key(neighbour->name));
    why = fmt::format("'{}' and '{}' ({}) would both define {}", name, other.name,
                      other.description, neighbour->identifier);
  } else {
    why = fmt::format("'{}' names the files every build writes once ({}.*) ignoring case", name,
                      name_key);
  }
  // `<stem>_<n>` within the length limit, never with "__" (the stem loses a trailing '_').
  std::string stem = name;
  for (int n = 2;; ++n) {
    const std::string suffix = fmt::format("_{}", n);
    stem.resize(std::min(stem.size(), kMaxMaterialNameLength - suffix.size()));
    while (!stem.empty() && stem.back() == '_')
      stem.pop_back();
    const std::string derived = stem + suffix;
    const std::string key = material_name_key(derived);
    if (taken_.contains(key) || reserved.contains(key) || shared_stems.contains(key) ||
        neighbour_in(taken_, key) || neighbour_in(reserved, key))
      continue;
    const std::string_view rule =
        taken != taken_.end() ? "material names that differ ignoring case (they name files)"
        : neighbour ? "material names that differ by more than a 'preintegrated_' or 'textured_' "
                      "in front (it is part of the generated names)"
                    : "a material name other than the shared files' (matc_lut, matc_fresnel, ...)";
    diagnostics.note(location, field, fmt::format("imported as '{}': {}", derived, why),
                     fmt::format("{}; the glTF loaders match materials by index", rule));
    taken_.emplace(key, First{derived, description});
    return derived;
  }
}

}  // namespace matc
