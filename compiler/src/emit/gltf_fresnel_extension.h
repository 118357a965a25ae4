// glTF out (docs/gltf.md): an asset written back with each metal's compiled coefficients in the
// vendor extension MATC_materials_fresnel, every other byte of the asset as it was. The JSON is
// edited in place (the extension inserted into each material's `extensions`, its name into
// `extensionsUsed`), not re-serialised, so the asset's own formatting, numbers, key order and
// data stay; a GLB's chunks after the JSON chunk are carried byte for byte.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/diagnostics.h"
#include "compile/compile.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/f0_table.h"

namespace matc {

inline constexpr std::string_view kGltfFresnelExtension = "MATC_materials_fresnel";

// The extension's object for a compiled metal (docs/gltf/MATC_materials_fresnel.schema.json):
// matc's name for it, the basis and matc version the coefficients belong to, the working colour
// space, the coefficients (rows R, G, B: c_0..c_3), their largest error against the exact curve,
// and a coated metal's coat. `zero_f0`: for a metal whose F0 varies per pixel (a textured Schlick
// metal), the same curve compiled at F0 = 0 (zeroF0Coefficients). `f0_table`: for a textured
// metal under an edge colour or a coat, its F0 table (f0Table: the coefficients in air and under
// the coat at each entry's F0).
nlohmann::ordered_json gltf_fresnel_extension(const CompiledMaterial& compiled,
                                              const runtime::BasisView& basis,
                                              const CompiledMaterial* zero_f0 = nullptr,
                                              const runtime::F0Table* f0_table = nullptr);

struct GltfWithExtensions {
  std::string bytes;  // the asset, in its own container
  // The relative URIs of the files its buffers and images name (not data URIs): what a .gltf
  // needs beside it.
  std::vector<std::string> external_uris;
};

// `asset` (a GLB when `binary`, else a .gltf's JSON), named `path` in diagnostics, with
// `extensions[i]` as materials[i]'s MATC_materials_fresnel: inserted, or replacing the one an
// earlier run wrote; a material not in `extensions` loses one it carried (its metal is gone).
// The extension is listed in extensionsUsed (when `extensions` is not empty), not
// extensionsRequired: an engine without it loads the asset's core material. Empty after an error (a
// key given twice, an `extensions` that is not an object: entries a reader could take two ways).
std::optional<GltfWithExtensions> gltf_with_fresnel_extensions(
    std::string_view asset, bool binary,
    const std::map<std::size_t, nlohmann::ordered_json>& extensions, const std::string& path,
    Diagnostics& diagnostics);

}  // namespace matc
