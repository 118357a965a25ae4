// matc.Material: a validated material (from a material file, JSON text, a dict, a MaterialX
// document or a glTF asset) with the warnings and notes its input gave.
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.h"
#include "errors.h"
#include "matc/matc.h"

namespace py = pybind11;

namespace matc::python {
namespace {

// The model's values as a dict of the material file's field names.
py::dict model_inputs(const api::Material& material) {
  const api::ModelInputs inputs = material.inputs();
  py::dict out;
  for (const auto& [name, rgb] : inputs.colors)
    out[py::str(name)] = py::cast(rgb);
  for (const auto& [name, text] : inputs.texts)
    out[py::str(name)] = python_text(text);
  return out;
}

}  // namespace

void register_materials(py::module_& module) {
  using api::Material;
  py::class_<Material>(
      module, "Material",
      "A validated material. Make one with matc.parse (a dict or JSON text), matc.load (a "
      "material file, MaterialX document or glTF asset) or matc.parse_materialx.")
      .def_property_readonly("name", [](const Material& m) { return python_text(m.name()); })
      .def_property_readonly("model", &Material::model,
                             "'artistic', 'ior', 'spectral' or 'f82_tint'")
      .def_property_readonly("inputs", &model_inputs,
                             "The model's values by the material file's field names")
      .def_property_readonly("roughness", &Material::roughness)
      .def_property_readonly("color_space", &Material::color_space)
      .def_property_readonly(
          "path", [](const Material& m) { return python_text(m.path()); },
          "The file (or the name given to a text) it was read from")
      .def_property_readonly(
          "json", [](const Material& m) { return python_text(m.json()); },
          "Its material file's JSON (for a MaterialX material, the file `matc import` writes)")
      .def_property_readonly(
          "diagnostics", [](const Material& m) { return diagnostic_list(m.diagnostics()); },
          "The input's warnings and notes")
      .def("__repr__", [](const Material& m) {
        return python_text("<matc.Material '" + m.name() + "' (" + m.model() + ") from " +
                           m.path() + ">");
      });

  module.def(
      "_parse_json",
      [](const std::string& text, const std::string& path) {
        return without_gil([&] { return api::parse_material_json(text, path); });
      },
      py::arg("text"), py::arg("path"));
  module.def(
      "_parse_input",
      [](const std::string& text, const std::string& path) {
        return without_gil([&] { return api::parse_materials(text, path); });
      },
      py::arg("text"), py::arg("path"));
  module.def(
      "_load",
      [](const std::string& path) {
        return without_gil([&] { return api::load_materials(path); });
      },
      py::arg("path"));
}

}  // namespace matc::python
