// Reading a glTF 2.0 asset (.gltf or .glb) with tinygltf, checked before anything uses it: the GLB
// container's chunks, every buffer (inside the asset's folder, of its declared length), every
// buffer view and accessor in range, image URIs inside the folder, array sizes bounded. A problem
// is an error naming the asset and the entry (`bufferViews[2]`), never a partial model.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "tinygltf_config.h"

#include "base/diagnostics.h"
#include "material/parse.h"

namespace matc {

// A URI's %XX sequences decoded: the relative file name it stands for.
std::string percent_decoded(std::string_view uri);

// The asset `bytes` named `path` (".glb": binary, else JSON), its external buffers read through
// `loader` from the asset's folder. Empty when `diagnostics` got an error.
std::optional<tinygltf::Model> read_gltf_asset(std::string_view bytes, const std::string& path,
                                               const FileLoader& loader, Diagnostics& diagnostics);

}  // namespace matc
