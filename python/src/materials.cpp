#include "materials.h"

#include <string>
#include <variant>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.h"
#include "errors.h"
#include "matc/material/material_input.h"
#include "matc/material/parse.h"
#include "matc/optics/color_space.h"

namespace py = pybind11;

namespace matc::python {
namespace {

std::vector<LoadedMaterialPointer> loaded(MaterialInput input) {
  if (input.diagnostics.has_errors() || input.materials.empty())
    throw MaterialErrorThrown(std::move(input.diagnostics));
  std::vector<LoadedMaterialPointer> materials;
  for (Material& material : input.materials)
    materials.push_back(
        std::make_shared<LoadedMaterial>(LoadedMaterial{std::move(material), input.diagnostics}));
  return materials;
}

// The model's values as a dict of the material file's field names.
py::dict model_inputs(const MaterialModel& model) {
  py::dict inputs;
  std::visit(
      [&](const auto& input) {
        using Input = std::decay_t<decltype(input)>;
        if constexpr (std::is_same_v<Input, ArtisticInput>) {
          inputs["reflectivity"] = input.reflectivity;
          inputs["edge_tint"] = input.edge_tint;
        } else if constexpr (std::is_same_v<Input, IorInput>) {
          inputs["n"] = input.n;
          inputs["k"] = input.k;
        } else if constexpr (std::is_same_v<Input, SpectralInput>) {
          if (!input.preset.empty()) inputs["preset"] = input.preset;
          if (!input.file.empty()) inputs["file"] = input.file;
        } else {
          inputs["f0"] = input.f0;
          inputs["tint"] = input.tint;
        }
      },
      model);
  return inputs;
}

}  // namespace

void register_materials(py::module_& module) {
  py::class_<LoadedMaterial, LoadedMaterialPointer>(
      module, "Material",
      "A validated material. Make one with matc.parse (a dict or JSON text), matc.load (a "
      "material file or MaterialX document) or matc.parse_materialx.")
      .def_property_readonly("name", [](const LoadedMaterial& m) { return m.material.name; })
      .def_property_readonly(
          "model", [](const LoadedMaterial& m) { return std::string(model_key(m.material.model)); },
          "'artistic', 'ior', 'spectral' or 'f82_tint'")
      .def_property_readonly(
          "inputs", [](const LoadedMaterial& m) { return model_inputs(m.material.model); },
          "The model's values by the material file's field names")
      .def_property_readonly("roughness",
                             [](const LoadedMaterial& m) { return m.material.roughness; })
      .def_property_readonly("color_space",
                             [](const LoadedMaterial& m) -> std::optional<std::string> {
                               if (!m.material.color_space) return std::nullopt;
                               return std::string(color_space_name(*m.material.color_space));
                             })
      .def_property_readonly(
          "path", [](const LoadedMaterial& m) { return m.material.source_path; },
          "The file (or the name given to a text) it was read from")
      .def_property_readonly(
          "json", [](const LoadedMaterial& m) { return m.material.source_text; },
          "Its material file's JSON (for a MaterialX material, the file `matc import` writes)")
      .def_property_readonly(
          "diagnostics", [](const LoadedMaterial& m) { return diagnostic_list(m.diagnostics); },
          "The input's warnings and notes")
      .def("__repr__", [](const LoadedMaterial& m) {
        return "<matc.Material '" + m.material.name + "' (" +
               std::string(model_key(m.material.model)) + ") from " + m.material.source_path + ">";
      });

  module.def(
      "_parse_json",
      [](const std::string& text, const std::string& path) {
        ParseResult parsed = parse_material(text, path);
        if (!parsed.material) throw MaterialErrorThrown(std::move(parsed.diagnostics));
        return std::make_shared<LoadedMaterial>(
            LoadedMaterial{std::move(*parsed.material), std::move(parsed.diagnostics)});
      },
      py::arg("text"), py::arg("path"));
  module.def(
      "_parse_input",
      [](const std::string& text, const std::string& path) {
        return loaded(parse_material_input(text, path));
      },
      py::arg("text"), py::arg("path"));
  module.def(
      "_load", [](const std::string& path) { return loaded(read_material_input(path)); },
      py::arg("path"));
}

}  // namespace matc::python
