// The `matc` Python module's compiled part, matc._matc (the package's __init__.py is its face).
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "matc/version.h"

PYBIND11_MODULE(_matc, module) {
  module.doc() = "matc's library: materials, coefficients, tables, shaders and batches";
  module.attr("__version__") = matc::kVersion;
  matc::python::register_errors(module);
  matc::python::register_materials(module);
  matc::python::register_compiled_material(module);
  matc::python::register_tables(module);
  matc::python::register_build(module);
  matc::python::register_batch(module);
  matc::python::register_gltf(module);
  matc::python::register_commands(module);
}
