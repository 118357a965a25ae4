// The GLB container of glTF 2.0 (binary glTF): a 12-byte header ("glTF", version 2, the file's
// length), a JSON chunk, then an optional BIN chunk, every chunk 4-byte aligned. Read to check an
// asset before tinygltf parses it, and written to carry an asset's chunks through a change of its
// JSON (docs/gltf.md).
#pragma once

#include <string>
#include <string_view>

namespace matc {

// Why `bytes` is not a GLB 2.0 container matc reads (a sentence), or empty when it is: the
// magic, the version, the header's length equal to the file's, a JSON chunk and an optional BIN
// chunk inside the file and 4-byte aligned (tinygltf's own check lets a BIN chunk end up to its
// 8-byte header past the file).
std::string glb_layout_problem(std::string_view bytes);

struct GlbParts {
  std::string_view json;        // the JSON chunk's data, its padding removed
  std::string_view after_json;  // every byte after the JSON chunk (the BIN chunk and any other)
};

// The parts of a GLB whose glb_layout_problem is empty.
GlbParts glb_parts(std::string_view bytes);

// A GLB of `json` (padded with spaces to 4 bytes) followed by `after_json` as it is.
std::string glb_file(std::string_view json, std::string_view after_json);

}  // namespace matc
