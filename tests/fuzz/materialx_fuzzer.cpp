// libFuzzer target for the MaterialX importer: arbitrary bytes as a .mtlx document. Whatever it
// reads, the importer must not crash, must report an error exactly when it imports nothing, and
// every material it returns must be one the material parser accepts from its own JSON and the
// compiler compiles. Built with -DMATC_BUILD_FUZZERS=ON (clang).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "diagnostic_properties.h"
#include "matc/compile/compile.h"
#include "matc/material/materialx_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const matc::MaterialXImport imported = matc::import_materialx(text, "fuzz.mtlx");
  if (imported.materials.empty() != imported.diagnostics.has_errors()) __builtin_trap();
  matc::fuzz::require_printable_diagnostics(imported.diagnostics);
  matc::fuzz::require_refused_if_nul(text, !imported.materials.empty());
  for (const matc::ImportedMaterial& material : imported.materials) {
    const matc::ParseResult reparsed = matc::parse_material(material.json, "fuzz.mtlx");
    if (!reparsed.material || reparsed.diagnostics.has_errors()) __builtin_trap();
    if (reparsed.material->name != material.material.name) __builtin_trap();
  }
  // Compiling is slow next to parsing: one material per input is enough to cover the paths.
  if (!imported.materials.empty()) {
    const auto compiled =
        matc::compile_material(imported.materials.front().material, matc::runtime::shipped_basis());
    for (const auto& channel : compiled.coefficients)
      for (const double c : channel)
        if (!(c == c)) __builtin_trap();  // no NaN
  }
  return 0;
}
