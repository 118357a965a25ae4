// matc.compile_gltf's native half: the public API's compile_gltf_file (matc/api/gltf.h), the
// asset written back with each metal's MATC_materials_fresnel and the metals it compiled (as the
// module's CompiledMaterial, read and compiled once); its errors as matc.MaterialError.
#include <string>
#include <vector>

#include "bindings.h"
#include "compiled_material.h"
#include "errors.h"
#include "matc/matc.h"
#include "matc/options/option_names.h"

namespace py = pybind11;

namespace matc::python {
namespace {

// The public API's diagnostics as the library's, which matc.MaterialError carries. Their text is
// already escaped; escaping it again when Python reads it changes nothing (no control bytes are
// left, and a backslash is kept as it is).
Diagnostics library_diagnostics(const std::vector<api::Diagnostic>& diagnostics) {
  Diagnostics out;
  for (const api::Diagnostic& item : diagnostics) {
    const SourceLocation location{item.path, item.line, item.column};
    if (item.severity == "error") {
      out.error(location, item.field, item.message, item.allowed);
    } else if (item.severity == "warning") {
      out.warning(location, item.field, item.message, item.allowed);
    } else {
      out.note(location, item.field, item.message, item.allowed);
    }
  }
  return out;
}

// (bytes, [CompiledMaterial]).
py::tuple compile_gltf(const std::string& path, const std::string& basis,
                       const std::string& color_space, const std::string& gamut_mapping) {
  api::GltfAsset asset;
  {
    const py::gil_scoped_release release;
    try {
      asset = api::compile_gltf_file(path, {basis, color_space, gamut_mapping});
    } catch (const api::MaterialError& error) {
      throw MaterialErrorThrown(library_diagnostics(error.diagnostics()));
    }
  }
  py::list materials;
  for (const api::CompiledMaterial& compiled : asset.materials) {
    const api::Material& material = compiled.material();
    auto loaded = std::make_shared<LoadedMaterial>(
        LoadedMaterial{material.value(), library_diagnostics(material.diagnostics())});
    materials.append(compiled_result(loaded, compiled.value(),
                                     *option_value<runtime::BasisKind>(compiled.basis()),
                                     compiled.value().color));
  }
  return py::make_tuple(py::bytes(asset.bytes), materials);
}

}  // namespace

void register_gltf(py::module_& module) {
  module.def("_compile_gltf", &compile_gltf, py::arg("path"), py::arg("basis"),
             py::arg("color_space"), py::arg("gamut_mapping"));
}

}  // namespace matc::python
