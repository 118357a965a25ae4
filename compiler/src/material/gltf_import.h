// Importing metals from glTF 2.0 assets (.gltf with its buffers, .glb): every metallic material
// becomes a matc material (docs/gltf.md). The core metal is Schlick's curve from
// baseColorFactor (matc's f82_tint model with a white tint); EXT_materials_specular_edge_color
// (inside KHR_materials_specular) makes the specular colour its F82 edge colour;
// KHR_materials_clearcoat (with KHR_materials_clearcoat_ior's index) its coat. What matc does not
// carry (textures, partial metalness, iridescence, anisotropy, ...) gets a note naming the material
// and the property. The asset is read with tinygltf (Debian's libtinygltf-dev) and checked
// before anything is imported: GLB chunks, buffers and their URIs (inside the asset's folder),
// buffer views and accessors in range, counts bounded.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "material/document_import.h"
#include "material/parse.h"

namespace matc {

// The asset (.gltf or .glb) and each external buffer read at most.
inline constexpr std::uintmax_t kMaxGltfFileBytes = 256u << 20;  // 256 MiB
// Entries of each top-level array (materials, accessors, buffers, ...) read at most.
inline constexpr std::size_t kMaxGltfArrayEntries = 1u << 20;

// Whether `path` names a glTF asset (".gltf" or ".glb", any case).
bool is_gltf_path(std::string_view path);

// Imports every metallic material of the asset `bytes` named `path`; external buffers are read
// through `loader`, relative to the asset's folder and never outside it.
DocumentImport import_gltf(std::string_view bytes, const std::string& path,
                           const FileLoader& loader = load_file);

}  // namespace matc
