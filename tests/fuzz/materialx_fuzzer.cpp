// libFuzzer target for the MaterialX importer: arbitrary bytes as a .mtlx document. Whatever it
// reads, the importer must not crash, must report an error exactly when it imports nothing, and
// every material it returns must be one the material parser accepts from its own JSON and the
// compiler compiles. Built with -DMATC_BUILD_FUZZERS=ON (clang).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "diagnostic_properties.h"
#include "material/materialx_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const matc::MaterialXImport imported = matc::import_materialx(text, "fuzz.mtlx");
  matc::fuzz::require_sound_import(imported, "fuzz.mtlx");
  matc::fuzz::require_refused_if_nul(text, !imported.materials.empty());
  return 0;
}
