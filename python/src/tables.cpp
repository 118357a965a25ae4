// matc.PreintegratedTable and matc.CoefficientTable: the public API's tables (matc/api/tables.h),
// their texels as read-only numpy arrays, their layouts, and sampling exactly as the CPU runtime
// (and a GPU sampler) reads them.
#include <algorithm>
#include <string>

#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "matc/api/options.h"
#include "matc/api/tables.h"
#include "numpy_arrays.h"

namespace py = pybind11;

namespace matc::python {
namespace {

using api::CoefficientTable;
using api::PreintegratedTable;

constexpr const char* kPreintegratedLayout =
    "texels[y, x, i] = bbar_i at NdotV = (x / (size - 1))^2 and perceptual roughness = "
    "y / (size - 1) (GGX alpha = roughness^2); texel centres on the ends of both axes: sample "
    "with linear filtering and clamp-to-edge at texcoord = (u * (size - 1) + 0.5) / size, "
    "u = sqrt(NdotV) (docs/lut.md)";
constexpr const char* kCoefficientTableLayout =
    "texels[y, x] = (c_2, c_3) of one channel at u = (r^(1/4) + r^2) / 2 = x / (size - 1) and "
    "v = 1 - sqrt(1 - g) = y / (size - 1); c_0 = r, c_1 = 1 - r; sample like the preintegrated "
    "table (docs/coefficient-table.md)";

// The texels as a read-only (size, size, width) array that keeps the table alive.
template <typename Table>
py::array_t<float> texel_view(const Table& table, std::size_t width) {
  const auto size = static_cast<py::ssize_t>(table.size());
  return read_only_view(table.texels().data(), {size, size, static_cast<py::ssize_t>(width)},
                        table);
}

}  // namespace

void register_tables(py::module_& module) {
  py::class_<PreintegratedTable>(module, "PreintegratedTable",
                                 "The split-sum table bbar_0..bbar_3 (NdotV, roughness) of a basis")
      .def_property_readonly("size", &PreintegratedTable::size)
      .def_property_readonly("samples", &PreintegratedTable::samples)
      .def_property_readonly("basis", &PreintegratedTable::basis)
      .def_property_readonly("precision", &PreintegratedTable::precision)
      .def_property_readonly(
          "texels", [](const PreintegratedTable& t) { return texel_view(t, 4); },
          "float32 array (size, size, 4), rows by roughness: see layout")
      .def_property_readonly_static("layout",
                                    [](const py::object&) { return kPreintegratedLayout; })
      .def(
          "sample",
          [](const PreintegratedTable& t, const py::object& ndotv_values,
             const py::object& roughness_values) {
            return map_pair_chunks<4>(
                ndotv_roughness_pair(ndotv_values, roughness_values),
                [&](const double* ndotv, const double* roughness, std::size_t count, double* out) {
                  const std::vector<double> bbar = t.sample({ndotv, count}, {roughness, count});
                  std::copy(bbar.begin(), bbar.end(), out);
                });
          },
          py::arg("ndotv"), py::arg("roughness"),
          "bbar_0..bbar_3, bilinearly filtered as a GPU sampler reads the table: shape "
          "broadcast(ndotv, roughness) + (4,)")
      .def("__repr__", [](const PreintegratedTable& t) {
        return fmt::format("<matc.PreintegratedTable {}x{} {} {} samples={}>", t.size(), t.size(),
                           t.basis(), t.precision(), t.samples());
      });

  module.def(
      "preintegrated_table",
      [](const std::string& basis, std::size_t size, std::size_t samples,
         const std::string& precision) {
        const py::gil_scoped_release release;  // a bake takes a while; another may be running
        return api::preintegrated_table({basis, size, samples, precision});
      },
      py::arg("basis") = api::option_default("basis"),
      py::arg("size") = api::kDefaultLutSize, py::arg("samples") = api::kDefaultLutSamples,
      py::arg("precision") = "f32",
      "The preintegrated table as matc writes it (f16: rounded as the file stores it); baked once "
      "per process for each set of arguments.");

  py::class_<CoefficientTable>(module, "CoefficientTable",
                               "c_2, c_3 of one channel as a function of Gulbrandsen's r, g")
      .def_property_readonly("size", &CoefficientTable::size)
      .def_property_readonly("basis", &CoefficientTable::basis)
      .def_property_readonly("precision", &CoefficientTable::precision)
      .def_property_readonly(
          "texels", [](const CoefficientTable& t) { return texel_view(t, 2); },
          "float32 array (size, size, 2), rows by edge tint: see layout")
      .def_property_readonly_static("layout",
                                    [](const py::object&) { return kCoefficientTableLayout; })
      .def(
          "coefficients",
          [](const CoefficientTable& t, const api::Rgb& reflectivity, const api::Rgb& edge_tint) {
            return matrix_array(t.coefficients(reflectivity, edge_tint));
          },
          py::arg("reflectivity"), py::arg("edge_tint"),
          "c_0..c_3 per channel (3, 4) from the table, as the shaders' "
          "matc_coefficients_from_table computes them")
      .def("__repr__", [](const CoefficientTable& t) {
        return fmt::format("<matc.CoefficientTable {}x{} {} {}>", t.size(), t.size(), t.basis(),
                           t.precision());
      });

  module.def(
      "coefficient_table",
      [](const std::string& basis, const std::string& precision) {
        return api::coefficient_table(basis, precision);
      },
      py::arg("basis") = api::option_default("basis"), py::arg("precision") = "f16",
      "The basis' coefficient table as matc_coefficient_table.* stores it (f16 by default).");
}

}  // namespace matc::python
