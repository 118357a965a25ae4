// matc.CompiledMaterial: a material's coefficients with what they were fitted to, evaluated over
// numpy arrays exactly as the CPU runtime (and so the shaders) computes them.
#include <algorithm>
#include <string>

#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "errors.h"
#include "matc/api/tables.h"
#include "matc/matc.h"
#include "numpy_arrays.h"

namespace py = pybind11;

namespace matc::python {
namespace {

using api::CompiledMaterial;

// `values` (count RGB triples, or any width) copied into out.
void copy_rows(const std::vector<double>& values, double* out) {
  std::copy(values.begin(), values.end(), out);
}

py::dict accuracy_dict(const api::Accuracy& accuracy) {
  py::dict out;
  out["samples"] = accuracy.samples;
  out["max_error"] = vector_array(accuracy.max_error);
  out["rms_error"] = vector_array(accuracy.rms_error);
  out["schlick_max_error"] = vector_array(accuracy.schlick_max_error);
  out["schlick_rms_error"] = vector_array(accuracy.schlick_rms_error);
  out["f82_tint_max_error"] = vector_array(accuracy.f82_tint_max_error);
  out["f82_tint_rms_error"] = vector_array(accuracy.f82_tint_rms_error);
  return out;
}

py::object ior_array(const CompiledMaterial& compiled) {
  const auto ior = compiled.ior();
  if (!ior) return py::none();
  std::array<std::array<double, 2>, 3> rows{};
  for (std::size_t c = 0; c < 3; ++c)
    rows[c] = {ior->n[c], ior->k[c]};
  return matrix_array(rows);
}

py::object artistic_dict(const CompiledMaterial& compiled) {
  const auto artistic = compiled.artistic();
  if (!artistic) return py::none();
  py::dict out;
  out["reflectivity"] = vector_array(artistic->reflectivity);
  out["edge_tint"] = vector_array(artistic->edge_tint);
  return out;
}

py::object coat_dict(const CompiledMaterial& compiled) {
  const auto coat = compiled.coat();
  if (!coat) return py::none();
  py::dict out;
  out["weight"] = coat->weight;
  out["ior"] = coat->ior;
  out["roughness"] = coat->roughness;
  out["color"] = vector_array(coat->color);
  out["under_coat_coefficients"] = matrix_array(coat->under_coat_coefficients);
  out["coat_coefficients"] = vector_array(coat->coat_coefficients);
  out["layered_max_error"] = vector_array(coat->layered_max_error);
  return out;
}

// An RGB curve over an array of cosines: `curve(compiled, cosines)` on chunks, on threads.
template <typename Curve>
py::array_t<double> rgb_curve(const CompiledMaterial& compiled, const py::object& mu_values,
                              const Curve& curve) {
  const DoubleArray mu = unit_interval_array(mu_values, "mu");
  return map_value_chunks<3>(mu, [&](const double* cosines, std::size_t count, double* rgb) {
    copy_rows(curve(compiled, std::span<const double>(cosines, count)), rgb);
  });
}

py::array_t<double> fbar(const CompiledMaterial& compiled, const py::object& ndotv_values,
                         const py::object& roughness_values, const api::PreintegratedTable* table) {
  const auto points = ndotv_roughness_pair(ndotv_values, roughness_values);
  if (table && table->basis() != compiled.basis()) {
    throw py::value_error(
        fmt::format("table: integrates the {} basis; this material is compiled against {}",
                    table->basis(), compiled.basis()));
  }
  return map_pair_chunks<3>(
      points, [&](const double* ndotv, const double* roughness, std::size_t count, double* rgb) {
        const std::span<const double> n(ndotv, count), r(roughness, count);
        if (table) {
          compiled.fbar(n, r, *table, {rgb, 3 * count});
        } else {
          compiled.fbar(n, r, {rgb, 3 * count});
        }
      });
}

py::array_t<double> fbar_reference(const CompiledMaterial& compiled, const py::object& ndotv_values,
                                   const py::object& roughness_values, std::size_t samples) {
  const auto points = ndotv_roughness_pair(ndotv_values, roughness_values);
  compiled.fbar_reference({}, {}, samples);  // the count checked here, before any thread
  // Each point is a Monte-Carlo integral: worth a thread from two points on.
  return map_pair_chunks<3>(
      points,
      [&](const double* ndotv, const double* roughness, std::size_t count, double* rgb) {
        copy_rows(compiled.fbar_reference({ndotv, count}, {roughness, count}, samples), rgb);
      },
      1);
}

// A (3, 4) array of c_0..c_3 per channel.
api::CoefficientRows coefficients_of(const py::object& given) {
  const DoubleArray values = real_array(given, "coefficients");
  if (values.ndim() != 2 || values.shape(0) != 3 || values.shape(1) != 4)
    throw py::value_error("coefficients: an array of shape (3, 4): rows R, G, B; columns c_0..c_3");
  api::CoefficientRows coefficients{};
  const auto view = values.unchecked<2>();
  for (py::ssize_t c = 0; c < 3; ++c)
    for (py::ssize_t i = 0; i < 4; ++i)
      coefficients[c][i] = view(c, i);
  return coefficients;
}

double worst_channel(const api::Rgb& values) {
  return *std::max_element(values.begin(), values.end());
}

}  // namespace

void register_compiled_material(py::module_& module) {
  module.def(
      "fresnel_from_coefficients",
      [](const py::object& coefficients, const py::object& mu_values, const std::string& basis) {
        const api::CoefficientRows values = coefficients_of(coefficients);
        api::fresnel_from_coefficients(values, {}, basis);  // checked here, before any thread
        const DoubleArray mu = unit_interval_array(mu_values, "mu");
        return map_value_chunks<3>(mu, [&](const double* cosines, std::size_t count, double* rgb) {
          copy_rows(api::fresnel_from_coefficients(values, {cosines, count}, basis), rgb);
        });
      },
      py::arg("coefficients"), py::arg("mu"), py::arg("basis") = api::option_default("basis"),
      "F(mu) for any (3, 4) coefficients (a coefficient table's, a texture's) as the shaders "
      "compute it");

  py::class_<CompiledMaterial>(
      module, "CompiledMaterial",
      "A material's decomposition: coefficients c_0..c_3 per RGB channel against a basis, with "
      "the exact curve they were fitted to. Every evaluation takes numpy arrays (or numbers) and "
      "returns the input's shape plus an RGB axis.")
      .def_property_readonly("name",
                             [](const CompiledMaterial& r) { return python_text(r.name()); })
      .def_property_readonly("material", &CompiledMaterial::material)
      .def_property_readonly(
          "coefficients", [](const CompiledMaterial& r) { return matrix_array(r.coefficients()); },
          "float64 array (3, 4): rows R, G, B; columns c_0..c_3")
      .def_property_readonly("basis", &CompiledMaterial::basis)
      .def_property_readonly("color_space", &CompiledMaterial::color_space)
      .def_property_readonly("gamut_mapping", &CompiledMaterial::gamut_mapping)
      .def_property_readonly(
          "f0", [](const CompiledMaterial& r) { return vector_array(r.f0()); },
          "Exact reflectance at normal incidence, RGB")
      .def_property_readonly(
          "f82", [](const CompiledMaterial& r) { return vector_array(r.f82()); },
          "Exact reflectance at mu = 1/7 (about 82 degrees), RGB")
      .def_property_readonly(
          "average_fresnel",
          [](const CompiledMaterial& r) { return vector_array(r.average_fresnel()); },
          "Cosine-weighted average of the decomposed Fresnel, RGB")
      .def_property_readonly("ior", &ior_array,
                             "(3, 2) array of n, k per channel; None for spectral materials")
      .def_property_readonly("artistic", &artistic_dict,
                             "Gulbrandsen's reflectivity and edge tint per channel; None for "
                             "spectral")
      .def_property_readonly(
          "accuracy", [](const CompiledMaterial& r) { return accuracy_dict(r.accuracy()); },
          "Max and RMS |F - exact| per channel for ours, Schlick's and F82-tint's")
      .def_property_readonly(
          "coat", &coat_dict,
          "A coated material's coat (docs/coating.md): its inputs, the under-coat and coat "
          "coefficients and the layered max error; None for a bare metal")
      .def_property_readonly(
          "film_table",
          [](const CompiledMaterial& r) -> py::object {
            std::optional<matc::api::FilmTable> film = r.film_table();
            if (!film) return py::none();
            py::array_t<float> texels({film->height, film->width, std::size_t{4}});
            std::copy(film->texels.begin(), film->texels.end(), texels.mutable_data());
            return texels;
          },
          "A filmed metal's own table (docs/thin-film.md): (18, 65, 4) float32 RGBA texels, "
          "row 0 F over sqrt(mu), rows 1-17 Fbar; None without a film")
      .def_property_readonly("saturation", &CompiledMaterial::saturation)
      .def_property_readonly("fresnel_nonnegative", &CompiledMaterial::fresnel_nonnegative)
      .def_property_readonly(
          "diagnostics", [](const CompiledMaterial& r) { return diagnostic_list(r.diagnostics()); },
          "Warnings and notes, as matc prints them")
      .def(
          "fresnel",
          [](const CompiledMaterial& r, const py::object& mu_values) {
            const DoubleArray mu = unit_interval_array(mu_values, "mu");
            return map_value_chunks<3>(mu,
                                       [&](const double* cosines, std::size_t count, double* rgb) {
                                         r.fresnel({cosines, count}, {rgb, 3 * count});
                                       });
          },
          py::arg("mu"),
          "F(mu) = max(0, sum c_i b_i(mu)) as the shaders compute it (the shaders' polynomial "
          "basis); for a coated material both lobes' sum")
      .def(
          "exact",
          [](const CompiledMaterial& r, const py::object& mu) {
            return rgb_curve(r, mu, [](const CompiledMaterial& m, std::span<const double> x) {
              return m.exact(x);
            });
          },
          py::arg("mu"),
          "The exact curve the coefficients were fitted to; for a coated material the exact "
          "layered reflectance")
      .def(
          "schlick",
          [](const CompiledMaterial& r, const py::object& mu) {
            return rgb_curve(r, mu, [](const CompiledMaterial& m, std::span<const double> x) {
              return m.schlick(x);
            });
          },
          py::arg("mu"), "Schlick's curve with the exact F0")
      .def("fbar", &fbar, py::arg("ndotv"), py::arg("roughness"), py::arg("table") = nullptr,
           "The preintegrated Fresnel sum c_i bbar_i(NdotV, roughness), one table fetch as a "
           "renderer does (table: matc's default for the basis unless given)")
      .def("fbar_reference", &fbar_reference, py::arg("ndotv"), py::arg("roughness"),
           py::arg("samples") = CompiledMaterial::kReferenceSamples,
           "The exact split-sum integral of the exact curve (Monte Carlo, no basis or table)")
      .def(
          "to_dict",
          [](const CompiledMaterial& r) {
            return py::module_::import("json").attr("loads")(r.json());
          },
          "What <name>.json holds (less the inputs hash, which depends on the build's options)")
      .def("__repr__", [](const CompiledMaterial& r) {
        return python_text(fmt::format("<matc.CompiledMaterial '{}' basis={} max_error={:.4f}>",
                                       r.name(), r.basis(), worst_channel(r.accuracy().max_error)));
      });
}

}  // namespace matc::python
