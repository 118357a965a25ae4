// The per-material output `<name>.json` (field reference: docs/material-format.md).
#pragma once

#include <nlohmann/json.hpp>

#include "matc/compile/compile.h"
#include "matc/runtime/basis.h"

namespace matc {

nlohmann::ordered_json compiled_material_json(const CompiledMaterial& compiled,
                                              const runtime::BasisView& basis);

}  // namespace matc
