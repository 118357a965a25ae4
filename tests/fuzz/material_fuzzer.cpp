// libFuzzer target: any bytes as a material file, through the parser and, when it parses, the
// whole compile of that one material (fit, accuracy, emitted GLSL/HLSL, SPIR-V, header, JSON).
// Spectral files it names are served from memory. Built with -DMATC_BUILD_FUZZERS=ON (clang);
// tests/fuzz/README.md says how to run it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "compile/compile.h"
#include "diagnostic_properties.h"
#include "emit/build.h"
#include "material/parse.h"

namespace {

// Every referenced file is this small, valid n,k table: the fuzzer explores the material file.
matc::LoadedFile serve_from_memory(const std::filesystem::path&, std::uintmax_t) {
  return {std::string("wavelength_nm,n,k\n380,0.5,3\n580,0.45,3.2\n780,0.4,4\n"), {}};
}

const matc::Build& small_build() {
  static const matc::Build build = [] {
    matc::BuildOptions options;
    options.lut.size = 4;  // the table is not what is fuzzed here
    options.lut.samples = 8;
    return matc::Build(options);
  }();
  return build;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  matc::ParseResult parsed = matc::parse_material(text, "fuzz/material.json", serve_from_memory);
  matc::fuzz::require_printable_diagnostics(parsed.diagnostics);
  matc::fuzz::require_refused_if_nul(text, parsed.material.has_value());
  if (!parsed.material) return 0;
  const matc::CompiledMaterial compiled =
      matc::compile_material(*parsed.material, matc::runtime::shipped_basis());
  matc::Diagnostics warnings;
  matc::warn_if_poor_fit(compiled, warnings);
  matc::fuzz::require_printable_diagnostics(warnings);
  const matc::MaterialOutputs outputs = small_build().material_outputs(compiled);
  if (outputs.files.empty()) __builtin_trap();  // a valid material always has outputs
  return 0;
}
