// One material's C/C++ header (<name>.h): coefficients in the shaders' buffer layout, the LUT it
// is sampled with, and its SPIR-V library module as words.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "compile/compile.h"
#include "formats/table_format.h"
#include "spirv/shader_compiler.h"

namespace matc {

struct LutReference {
  std::string file;  // as written beside the header, e.g. "matc_lut.ktx2"
  std::size_t size = 0;
  std::string hash;   // hash_of_bytes of that file
  std::string basis;  // the basis it integrates (and the coefficients were solved for)
  LutPrecision precision = LutPrecision::f32;  // its texels' (and a film table's)
};

// `lut_layer`: the material's layer of a per-material build's table (--basis auto), else none.
std::string material_c_header(const CompiledMaterial& compiled, std::string_view inputs_hash,
                              const LutReference& lut, const SpirvWords& library_module,
                              std::optional<std::size_t> lut_layer = std::nullopt);

}  // namespace matc
