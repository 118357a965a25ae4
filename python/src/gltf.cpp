// matc.compile_gltf's native half: the public API's compile_gltf_file (matc/api/gltf.h), the
// asset written back with each metal's MATC_materials_fresnel and the metals it compiled; its
// errors as matc.MaterialError.
#include <string>

#include <pybind11/stl.h>

#include "bindings.h"
#include "matc/matc.h"

namespace py = pybind11;

namespace matc::python {
namespace {

// (bytes, [CompiledMaterial]).
py::tuple compile_gltf(const std::string& path, const std::string& basis,
                       const std::string& color_space, const std::string& gamut_mapping) {
  api::GltfAsset asset;
  {
    const py::gil_scoped_release release;
    asset = api::compile_gltf_file(path, {basis, color_space, gamut_mapping});
  }
  return py::make_tuple(py::bytes(asset.bytes), py::cast(std::move(asset.materials)));
}

}  // namespace

void register_gltf(py::module_& module) {
  module.def("_compile_gltf", &compile_gltf, py::arg("path"), py::arg("basis"),
             py::arg("color_space"), py::arg("gamut_mapping"));
}

}  // namespace matc::python
