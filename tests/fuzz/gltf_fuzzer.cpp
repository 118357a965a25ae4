// libFuzzer target for the glTF importer: arbitrary bytes as a .glb (first byte odd) or a .gltf
// asset (the rest). Whatever it reads, the importer must not crash, must report an error exactly
// when it imports nothing, must read no file (external buffers are refused through a loader that
// holds none), and every material it returns must be one the material parser accepts from its own
// JSON and the compiler compiles. An asset it imports is then written back with an extension in
// each metal (glTF out, emit/gltf_fresnel_extension.h): refused with printable errors, or
// written as an asset that imports again to the same materials (a GLB still a sound container)
// and that a second run leaves byte for byte. Built with -DMATC_BUILD_FUZZERS=ON (clang).
#include <cstddef>
#include <cstdint>
#include <map>
#include <string_view>

#include "diagnostic_properties.h"
#include "emit/gltf_fresnel_extension.h"
#include "formats/glb_container.h"
#include "material/gltf_import.h"

namespace {

// glTF out's properties on an asset `imported` read from `bytes`.
void require_sound_export(std::string_view bytes, bool binary, const char* path,
                          const matc::DocumentImport& imported, const matc::FileLoader& no_files) {
  std::map<std::size_t, nlohmann::ordered_json> extensions;
  for (const matc::ImportedMaterial& material : imported.materials)
    extensions.emplace(material.document_index,
                       nlohmann::ordered_json{{"name", material.material.name}});
  matc::Diagnostics diagnostics;
  const auto written =
      matc::gltf_with_fresnel_extensions(bytes, binary, extensions, path, diagnostics);
  matc::fuzz::require_printable_diagnostics(diagnostics);
  if (!written) {
    if (!diagnostics.has_errors()) __builtin_trap();
    return;
  }
  if (binary && !matc::glb_layout_problem(written->bytes).empty()) __builtin_trap();
  const matc::DocumentImport again = matc::import_gltf(written->bytes, path, no_files);
  if (again.materials.size() != imported.materials.size()) __builtin_trap();
  for (std::size_t i = 0; i < again.materials.size(); ++i)
    if (again.materials[i].json != imported.materials[i].json) __builtin_trap();
  matc::Diagnostics second_diagnostics;
  const auto second = matc::gltf_with_fresnel_extensions(written->bytes, binary, extensions, path,
                                                         second_diagnostics);
  if (!second || second->bytes != written->bytes) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool binary = (data[0] & 1u) != 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  const matc::FileLoader no_files = [](const std::filesystem::path&, std::uintmax_t) {
    return matc::LoadedFile{std::nullopt, "no files while fuzzing"};
  };
  const matc::DocumentImport imported =
      matc::import_gltf(bytes, binary ? "fuzz.glb" : "fuzz.gltf", no_files);
  matc::fuzz::require_sound_import(imported, "fuzz.gltf", /*empty_is_valid=*/true);
  // An asset without a metal is written too (unchanged but for a stale extension).
  if (!imported.diagnostics.has_errors())
    require_sound_export(bytes, binary, binary ? "fuzz.glb" : "fuzz.gltf", imported, no_files);
  return 0;
}
