// glTF out (docs/gltf.md): the metals of a glTF asset compiled and written back into it, each in
// the vendor extension MATC_materials_fresnel (its coefficients, basis, coat), every other byte
// of the asset carried through: `matc gltf`, Python's matc.compile_gltf and the npm package's
// compileGltf are this call.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "matc/api/compiled_material.h"

namespace matc::api {

struct GltfAsset {
  std::string bytes;  // the asset, in its own container (.glb or .gltf)
  std::vector<CompiledMaterial>
      materials;  // its metals compiled, in the asset's order (maybe none)
  // The asset's own notes (materials skipped, names derived, what is not carried); each compiled
  // material's diagnostics begin with these too.
  std::vector<Diagnostic> notes;
  // The relative URIs of the files a .gltf names beside it (buffers, images; not data URIs):
  // the written asset needs them beside it too.
  std::vector<std::string> external_uris;
};

// The asset `bytes` called `path` (".glb" binary, ".gltf" JSON, any case; a .gltf's external
// buffers resolve against path's folder) with its metals compiled with `options`. Throws
// MaterialError with the asset's errors (as parse_materials reads it), std::invalid_argument for
// a path that names no glTF asset or an option outside its names. An asset with no metal is
// returned unchanged (but for a MATC_materials_fresnel an earlier run wrote), with a note.
GltfAsset compile_gltf(std::string_view bytes, std::string_view path,
                       const CompileOptions& options = {});
// The same with the files a .gltf names (buffers, images) given in memory (parse_materials'
// InputFiles): they are the only files read.
GltfAsset compile_gltf(std::string_view bytes, std::string_view path, const CompileOptions& options,
                       const InputFiles& files);
// The same for the asset at `path`.
GltfAsset compile_gltf_file(std::string_view path, const CompileOptions& options = {});

// What write_gltf wrote beside the asset: the files a .gltf names, copied (relative paths,
// decoded).
struct GltfFilesCopied {
  std::vector<std::string> written;
  std::vector<std::string> unchanged;  // already there with the same bytes
};

// `asset`, compiled from the asset at `input`, written to `output` (native builds only), as
// `matc gltf -o` writes it: when `output` is in another folder, the files a .gltf names beside it
// (buffers, images) are copied beside `output` at the same relative paths, so its URIs resolve
// there; the files first, the asset last, each through a file with no name until it is complete.
// Never over an input (the asset or a file it names). Throws std::invalid_argument naming the
// problem before anything is written (paths escaped), std::runtime_error for a failed write.
GltfFilesCopied write_gltf(const GltfAsset& asset, std::string_view input, std::string_view output);

}  // namespace matc::api
