// The parts of the `matc` Python module: module.cpp calls one registration function per file;
// and what every part uses.
#pragma once

#include <pybind11/pybind11.h>

namespace matc::python {

void register_errors(pybind11::module_& module);             // errors.cpp
void register_materials(pybind11::module_& module);          // materials.cpp
void register_compiled_material(pybind11::module_& module);  // compiled_material.cpp
void register_tables(pybind11::module_& module);             // tables.cpp
void register_build(pybind11::module_& module);              // build.cpp
void register_batch(pybind11::module_& module);              // batch.cpp
void register_gltf(pybind11::module_& module);               // gltf.cpp
void register_commands(pybind11::module_& module);           // commands.cpp

// make() with the GIL released: the library's work (reading, compiling, baking, writing) lets
// other Python threads run.
template <typename Make>
auto without_gil(const Make& make) {
  const pybind11::gil_scoped_release release;
  return make();
}

}  // namespace matc::python
