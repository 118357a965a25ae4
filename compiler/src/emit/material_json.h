// The per-material output `<name>.json` (field reference: docs/material-format.md).
#pragma once

#include <nlohmann/json.hpp>

#include "compile/compile.h"
#include "matc/runtime/basis.h"

namespace matc {

// [r, g, b], and coefficient rows as [[c_0, c_1, c_2, c_3] per channel]: how matc's JSON outputs
// write them.
nlohmann::ordered_json rgb_json(const Rgb& rgb);
nlohmann::ordered_json coefficient_rows_json(const runtime::Coefficients& coefficients);

// `per_material_build`: the build gives each material its basis (--basis auto, the default); the
// JSON then names the material's layer of the table too (basis.lut_layer).
nlohmann::ordered_json compiled_material_json(const CompiledMaterial& compiled,
                                              const runtime::BasisView& basis,
                                              bool per_material_build);

}  // namespace matc
