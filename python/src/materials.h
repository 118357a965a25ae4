// matc.Material: a validated material (from a material file, JSON text, a dict or a MaterialX
// document) with the warnings and notes its input gave.
#pragma once

#include <memory>

#include <pybind11/pybind11.h>

#include "matc/base/diagnostics.h"
#include "matc/material/material.h"

namespace matc::python {

struct LoadedMaterial {
  Material material;
  Diagnostics diagnostics;  // the input's warnings and notes (errors raise instead)
};

using LoadedMaterialPointer = std::shared_ptr<LoadedMaterial>;

}  // namespace matc::python
