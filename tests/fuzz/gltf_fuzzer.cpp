// libFuzzer target for the glTF importer: arbitrary bytes as a .glb (first byte odd) or a .gltf
// asset (the rest). Whatever it reads, the importer must not crash, must report an error exactly
// when it imports nothing, must read no file (external buffers are refused through a loader that
// holds none), and every material it returns must be one the material parser accepts from its own
// JSON and the compiler compiles. Built with -DMATC_BUILD_FUZZERS=ON (clang).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "diagnostic_properties.h"
#include "matc/material/gltf_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool binary = (data[0] & 1u) != 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  const matc::FileLoader no_files = [](const std::filesystem::path&, std::uintmax_t) {
    return matc::LoadedFile{std::nullopt, "no files while fuzzing"};
  };
  const matc::DocumentImport imported =
      matc::import_gltf(bytes, binary ? "fuzz.glb" : "fuzz.gltf", no_files);
  matc::fuzz::require_sound_import(imported, "fuzz.gltf");
  return 0;
}
