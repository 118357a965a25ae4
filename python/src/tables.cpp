#include "tables.h"

#include <map>
#include <mutex>
#include <tuple>

#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "matc/lut/coefficient_table_files.h"
#include "matc/lut/lut_files.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/lut.h"
#include "numpy_arrays.h"
#include "option_values.h"

namespace py = pybind11;

namespace matc::python {
namespace {

constexpr const char* kPreintegratedLayout =
    "texels[y, x, i] = bbar_i at NdotV = (x / (size - 1))^2 and perceptual roughness = "
    "y / (size - 1) (GGX alpha = roughness^2); texel centres on the ends of both axes: sample "
    "with linear filtering and clamp-to-edge at texcoord = (u * (size - 1) + 0.5) / size, "
    "u = sqrt(NdotV) (docs/lut.md)";
constexpr const char* kCoefficientTableLayout =
    "texels[y, x] = (c_2, c_3) of one channel at u = (r^(1/4) + r^2) / 2 = x / (size - 1) and "
    "v = 1 - sqrt(1 - g) = y / (size - 1); c_0 = r, c_1 = 1 - r; sample like the preintegrated "
    "table (docs/coefficient-table.md)";

using TableKey = std::tuple<runtime::BasisKind, std::size_t, std::size_t, LutPrecision>;

// Tables are baked once per key and kept: a notebook that plots many materials pays once.
const PreintegratedTable& cached_table(const TableKey& key) {
  static std::mutex mutex;
  static std::map<TableKey, PreintegratedTable> tables;
  py::gil_scoped_release release;  // another thread may be baking while holding the mutex
  const std::lock_guard lock(mutex);
  auto found = tables.find(key);
  if (found == tables.end()) {
    const auto [basis, size, samples, precision] = key;
    LutOptions options;
    options.size = size;
    options.samples = samples;
    Lut baked = stored_as(preintegrate_lut(runtime::shipped_basis(basis), options), precision);
    found = tables
                .emplace(key, PreintegratedTable{std::make_shared<const Lut>(std::move(baked)),
                                                 basis, precision})
                .first;
  }
  return found->second;
}

py::array_t<float> lut_texels(const PreintegratedTable& table) {
  const auto size = static_cast<py::ssize_t>(table.lut->size);
  return read_only_view(table.lut->texels.data(), {size, size, 4}, table.lut);
}

}  // namespace

const PreintegratedTable& default_preintegrated_table(runtime::BasisKind basis) {
  return cached_table({basis, kDefaultLutSize, kDefaultLutSamples, LutPrecision::f32});
}

void register_tables(py::module_& module) {
  py::class_<PreintegratedTable>(module, "PreintegratedTable",
                                 "The split-sum table bbar_0..bbar_3 (NdotV, roughness) of a basis")
      .def_property_readonly("size", [](const PreintegratedTable& t) { return t.lut->size; })
      .def_property_readonly("samples", [](const PreintegratedTable& t) { return t.lut->samples; })
      .def_property_readonly(
          "basis",
          [](const PreintegratedTable& t) { return std::string(runtime::basis_name(t.basis)); })
      .def_property_readonly(
          "precision",
          [](const PreintegratedTable& t) { return std::string(lut_precision_name(t.precision)); })
      .def_property_readonly("texels", &lut_texels,
                             "float32 array (size, size, 4), rows by roughness: see layout")
      .def_property_readonly_static("layout",
                                    [](const py::object&) { return kPreintegratedLayout; })
      .def(
          "sample",
          [](const PreintegratedTable& t, const py::object& ndotv_values,
             const py::object& roughness_values) {
            const runtime::LutView view = t.lut->view();
            return map_pairs<runtime::kBasisSize>(
                ndotv_roughness_pair(ndotv_values, roughness_values),
                [&](double n, double r) { return runtime::sample_lut(view, n, r); });
          },
          py::arg("ndotv"), py::arg("roughness"),
          "bbar_0..bbar_3, bilinearly filtered as a GPU sampler reads the table: shape "
          "broadcast(ndotv, roughness) + (4,)")
      .def("__repr__", [](const PreintegratedTable& t) {
        return fmt::format("<matc.PreintegratedTable {}x{} {} {} samples={}>", t.lut->size,
                           t.lut->size, runtime::basis_name(t.basis),
                           lut_precision_name(t.precision), t.lut->samples);
      });

  module.def(
      "preintegrated_table",
      [](const std::string& basis, std::size_t size, std::size_t samples,
         const std::string& precision) {
        checked_count("size", size, kMinLutSize, kMaxLutSize);
        checked_count("samples", samples, 1, kMaxLutSamples);
        return cached_table({option_from_name<runtime::BasisKind>("basis", basis), size, samples,
                             option_from_name<LutPrecision>("precision", precision)});
      },
      py::arg("basis") = std::string(runtime::basis_name(runtime::kDefaultBasis)),
      py::arg("size") = kDefaultLutSize, py::arg("samples") = kDefaultLutSamples,
      py::arg("precision") = "f32",
      "The preintegrated table as matc writes it (f16: rounded as the file stores it); baked once "
      "per process for each set of arguments.");

  py::class_<CoefficientTableObject>(module, "CoefficientTable",
                                     "c_2, c_3 of one channel as a function of Gulbrandsen's r, g")
      .def_property_readonly("size",
                             [](const CoefficientTableObject& t) { return t.table->size(); })
      .def_property_readonly("basis",
                             [](const CoefficientTableObject& t) {
                               return std::string(runtime::basis_name(t.table->basis));
                             })
      .def_property_readonly("precision",
                             [](const CoefficientTableObject& t) {
                               return std::string(lut_precision_name(t.precision));
                             })
      .def_property_readonly(
          "texels",
          [](const CoefficientTableObject& t) {
            const auto size = static_cast<py::ssize_t>(t.table->size());
            return read_only_view(t.table->texels.data(), {size, size, 2}, t.table);
          },
          "float32 array (size, size, 2), rows by edge tint: see layout")
      .def_property_readonly_static("layout",
                                    [](const py::object&) { return kCoefficientTableLayout; })
      .def(
          "coefficients",
          [](const CoefficientTableObject& t, const runtime::Rgb& reflectivity,
             const runtime::Rgb& edge_tint) {
            for (std::size_t c = 0; c < 3; ++c) {
              checked_in_range("reflectivity", reflectivity[c], 0.0, 1.0);
              checked_in_range("edge_tint", edge_tint[c], 0.0, 1.0);
            }
            const runtime::Coefficients coefficients =
                runtime::coefficients_from_table(t.table->view(), reflectivity, edge_tint);
            return matrix_array(coefficients);
          },
          py::arg("reflectivity"), py::arg("edge_tint"),
          "c_0..c_3 per channel (3, 4) from the table, as the shaders' "
          "matc_coefficients_from_table computes them")
      .def("__repr__", [](const CoefficientTableObject& t) {
        return fmt::format("<matc.CoefficientTable {}x{} {} {}>", t.table->size(), t.table->size(),
                           runtime::basis_name(t.table->basis), lut_precision_name(t.precision));
      });

  module.def(
      "coefficient_table",
      [](const std::string& basis, const std::string& precision) {
        const LutPrecision stored = option_from_name<LutPrecision>("precision", precision);
        return CoefficientTableObject{
            std::make_shared<const CoefficientTable>(stored_coefficient_table(
                option_from_name<runtime::BasisKind>("basis", basis), stored)),
            stored};
      },
      py::arg("basis") = std::string(runtime::basis_name(runtime::kDefaultBasis)),
      py::arg("precision") = "f16",
      "The basis' coefficient table as matc_coefficient_table.* stores it (f16 by default).");
}

}  // namespace matc::python
