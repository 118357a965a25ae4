#include "compiled_material.h"

#include <cmath>
#include <optional>
#include <string>

#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "errors.h"
#include "matc/base/json_format.h"
#include "matc/emit/material_json.h"
#include "matc/lut/layered_reference.h"
#include "matc/lut/split_sum_reference.h"
#include "matc/optics/coat.h"
#include "matc/optics/fresnel.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"
#include "numpy_arrays.h"
#include "option_values.h"
#include "tables.h"

namespace py = pybind11;

namespace matc::python {

CompiledPointer compile_loaded(const LoadedMaterialPointer& material, runtime::BasisKind basis,
                               const ColorOptions& color) {
  CompiledMaterial compiled;
  {
    py::gil_scoped_release release;
    compiled = compile_material(material->material, runtime::shipped_basis(basis), color);
  }
  return compiled_result(material, std::move(compiled), basis, color);
}

CompiledPointer compiled_result(const LoadedMaterialPointer& material, CompiledMaterial compiled,
                                runtime::BasisKind basis, const ColorOptions& color) {
  auto result = std::make_shared<CompiledResult>();
  result->compiled = std::move(compiled);
  {
    py::gil_scoped_release release;
    result->exact = make_reflectance_curve(material->material, color);
    if (const auto& coat = result->compiled.coat) {
      result->in_air = result->exact;
      result->under_coat = make_under_coat_curve(material->material, color.working_space);
      result->exact =
          std::make_shared<LayeredCurve>(*result->in_air, *result->under_coat, coat->input.weight,
                                         coat->input.ior, coat->input.color);
    }
  }
  result->basis = basis;
  result->material = material;
  result->diagnostics = material->diagnostics;
  warn_if_poor_fit(result->compiled, result->diagnostics);
  note_if_out_of_unit_range(result->compiled, result->diagnostics);
  return result;
}

namespace {

py::dict accuracy_dict(const FitAccuracy& accuracy) {
  py::dict out;
  out["samples"] = accuracy.samples;
  out["max_error"] = vector_array(accuracy.decomposition.max_abs);
  out["rms_error"] = vector_array(accuracy.decomposition.rms);
  out["schlick_max_error"] = vector_array(accuracy.schlick.max_abs);
  out["schlick_rms_error"] = vector_array(accuracy.schlick.rms);
  out["f82_tint_max_error"] = vector_array(accuracy.f82_tint.max_abs);
  out["f82_tint_rms_error"] = vector_array(accuracy.f82_tint.rms);
  return out;
}

py::object ior_array(const CompiledMaterial& compiled) {
  if (!compiled.ior) return py::none();
  std::array<std::array<double, 2>, 3> rows{};
  for (std::size_t c = 0; c < 3; ++c)
    rows[c] = {(*compiled.ior)[c].n, (*compiled.ior)[c].k};
  return matrix_array(rows);
}

py::object artistic_dict(const CompiledMaterial& compiled) {
  if (!compiled.artistic) return py::none();
  Rgb reflectivity{}, edge_tint{};
  for (std::size_t c = 0; c < 3; ++c) {
    reflectivity[c] = (*compiled.artistic)[c].reflectivity;
    edge_tint[c] = (*compiled.artistic)[c].edge_tint;
  }
  py::dict out;
  out["reflectivity"] = vector_array(reflectivity);
  out["edge_tint"] = vector_array(edge_tint);
  return out;
}

py::object coat_dict(const CompiledMaterial& compiled) {
  if (!compiled.coat) return py::none();
  const CompiledCoat& coat = *compiled.coat;
  py::dict out;
  out["weight"] = coat.input.weight;
  out["ior"] = coat.input.ior;
  out["roughness"] = coat.input.roughness;
  out["color"] = vector_array(coat.input.color);
  out["under_coat_coefficients"] = matrix_array(coat.coefficients.under_coat);
  std::array<double, runtime::kBasisSize> coat_coefficients = coat.coefficients.coat;
  out["coat_coefficients"] = vector_array(coat_coefficients);
  out["layered_max_error"] = vector_array(coat.layered_error.max_abs);
  return out;
}

py::array_t<double> fresnel(const CompiledResult& result, const py::object& mu_values) {
  const DoubleArray mu = unit_interval_array(mu_values, "mu");
  const runtime::ShaderBasis& basis = runtime::shipped_shader_basis(result.basis);
  const runtime::Coefficients& coefficients = result.compiled.coefficients;
  if (const auto& coat = result.compiled.coat) {
    return map_values<3>(mu, [&](double cosine) {
      return runtime::evaluate_coated_fresnel(coefficients, coat->coefficients, basis, cosine)
          .total();
    });
  }
  return map_value_chunks<3>(mu, [&](const double* cosines, std::size_t count, double* rgb) {
    runtime::evaluate_fresnel(coefficients, basis, {cosines, count}, {rgb, 3 * count});
  });
}

py::array_t<double> exact(const CompiledResult& result, const py::object& mu_values) {
  const DoubleArray mu = unit_interval_array(mu_values, "mu");
  const ReflectanceCurve& curve = *result.exact;
  return map_values<3>(mu, [&](double cosine) { return curve.at(cosine); });
}

py::array_t<double> schlick(const CompiledResult& result, const py::object& mu_values) {
  const DoubleArray mu = unit_interval_array(mu_values, "mu");
  const Rgb f0 = result.compiled.f0;
  return map_values<3>(mu, [&](double cosine) {
    return Rgb{fresnel_schlick(cosine, f0[0]), fresnel_schlick(cosine, f0[1]),
               fresnel_schlick(cosine, f0[2])};
  });
}

py::array_t<double> fbar(const CompiledResult& result, const py::object& ndotv_values,
                         const py::object& roughness_values, const PreintegratedTable* table) {
  const auto points = ndotv_roughness_pair(ndotv_values, roughness_values);
  if (!table) table = &default_preintegrated_table(result.basis);
  if (table->basis != result.basis) {
    throw py::value_error(
        fmt::format("table: integrates the {} basis; this material is compiled "
                    "against {}",
                    runtime::basis_name(table->basis), runtime::basis_name(result.basis)));
  }
  const runtime::LutView view = table->lut->view();
  const runtime::Coefficients& coefficients = result.compiled.coefficients;
  if (const auto& coat = result.compiled.coat) {
    return map_pairs<3>(points, [&](double n, double r) {
      return runtime::evaluate_coated_fbar(coefficients, coat->coefficients, view, n, r).total();
    });
  }
  return map_pairs<3>(
      points, [&](double n, double r) { return runtime::evaluate_fbar(coefficients, view, n, r); });
}

py::array_t<double> fbar_reference(const CompiledResult& result, const py::object& ndotv_values,
                                   const py::object& roughness_values, std::size_t samples) {
  const auto points = ndotv_roughness_pair(ndotv_values, roughness_values);
  checked_count("samples", samples, 16, std::size_t{1} << 26);
  std::optional<TabulatedCurve> tabulated, under_coat;
  {
    py::gil_scoped_release release;
    tabulated.emplace(result.in_air ? *result.in_air : *result.exact);
    if (result.under_coat) under_coat.emplace(*result.under_coat);
  }
  if (const auto& coat = result.compiled.coat) {
    // The split-sum layering with exact curves, as matc eval's Fbar_reference.
    return map_pairs<3>(
        points,
        [&](double n, double r) {
          return layered_split_sum(*tabulated, *under_coat, coat->input, n, r);
        },
        1);
  }
  // Each point is a Monte-Carlo integral: worth a thread from two points on.
  return map_pairs<3>(
      points,
      [&](double n, double r) { return SplitSumEstimator(n, r, samples).integrate(*tabulated); },
      1);
}

// A (3, 4) array of c_0..c_3 per channel as runtime coefficients, each finite.
runtime::Coefficients coefficients_of(const py::object& given) {
  const DoubleArray values = real_array(given, "coefficients");
  if (values.ndim() != 2 || values.shape(0) != 3 || values.shape(1) != runtime::kBasisSize)
    throw py::value_error("coefficients: an array of shape (3, 4): rows R, G, B; columns c_0..c_3");
  runtime::Coefficients coefficients{};
  const auto view = values.unchecked<2>();
  for (py::ssize_t c = 0; c < 3; ++c) {
    for (py::ssize_t i = 0; i < static_cast<py::ssize_t>(runtime::kBasisSize); ++i) {
      coefficients[c][i] = view(c, i);
      if (!std::isfinite(coefficients[c][i])) {
        throw py::value_error(
            fmt::format("coefficients: [{}, {}] is {}; a finite number", c, i, coefficients[c][i]));
      }
    }
  }
  return coefficients;
}

}  // namespace

void register_compiled_material(py::module_& module) {
  module.def(
      "fresnel_from_coefficients",
      [](const py::object& coefficients, const py::object& mu_values, const std::string& basis) {
        const runtime::Coefficients values = coefficients_of(coefficients);
        const DoubleArray mu = unit_interval_array(mu_values, "mu");
        const runtime::ShaderBasis& shader_basis =
            runtime::shipped_shader_basis(option_from_name<runtime::BasisKind>("basis", basis));
        return map_value_chunks<3>(mu, [&](const double* cosines, std::size_t count, double* rgb) {
          runtime::evaluate_fresnel(values, shader_basis, {cosines, count}, {rgb, 3 * count});
        });
      },
      py::arg("coefficients"), py::arg("mu"),
      py::arg("basis") = std::string(runtime::basis_name(runtime::kDefaultBasis)),
      "F(mu) for any (3, 4) coefficients (a coefficient table's, a texture's) as the shaders "
      "compute it");

  py::class_<CompiledResult, CompiledPointer>(
      module, "CompiledMaterial",
      "A material's decomposition: coefficients c_0..c_3 per RGB channel against a basis, with "
      "the exact curve they were fitted to. Every evaluation takes numpy arrays (or numbers) and "
      "returns the input's shape plus an RGB axis.")
      .def_property_readonly("name",
                             [](const CompiledResult& r) { return r.compiled.material.name; })
      .def_readonly("material", &CompiledResult::material)
      .def_property_readonly(
          "coefficients",
          [](const CompiledResult& r) { return matrix_array(r.compiled.coefficients); },
          "float64 array (3, 4): rows R, G, B; columns c_0..c_3")
      .def_property_readonly(
          "basis",
          [](const CompiledResult& r) { return std::string(runtime::basis_name(r.basis)); })
      .def_property_readonly("color_space",
                             [](const CompiledResult& r) {
                               return std::string(color_space_name(r.compiled.color.working_space));
                             })
      .def_property_readonly(
          "gamut_mapping",
          [](const CompiledResult& r) {
            return std::string(gamut_mapping_name(r.compiled.color.gamut_mapping));
          })
      .def_property_readonly(
          "f0", [](const CompiledResult& r) { return vector_array(r.compiled.f0); },
          "Exact reflectance at normal incidence, RGB")
      .def_property_readonly(
          "f82", [](const CompiledResult& r) { return vector_array(r.compiled.f82); },
          "Exact reflectance at mu = 1/7 (about 82 degrees), RGB")
      .def_property_readonly(
          "average_fresnel",
          [](const CompiledResult& r) { return vector_array(r.compiled.average_fresnel); },
          "Cosine-weighted average of the decomposed Fresnel, RGB")
      .def_property_readonly(
          "ior", [](const CompiledResult& r) { return ior_array(r.compiled); },
          "(3, 2) array of n, k per channel; None for spectral materials")
      .def_property_readonly(
          "artistic", [](const CompiledResult& r) { return artistic_dict(r.compiled); },
          "Gulbrandsen's reflectivity and edge tint per channel; None for spectral")
      .def_property_readonly(
          "accuracy", [](const CompiledResult& r) { return accuracy_dict(r.compiled.accuracy); },
          "Max and RMS |F - exact| per channel for ours, Schlick's and F82-tint's")
      .def_property_readonly(
          "coat", [](const CompiledResult& r) { return coat_dict(r.compiled); },
          "A coated material's coat (docs/coating.md): its inputs, the under-coat and coat "
          "coefficients and the layered max error; None for a bare metal")
      .def_property_readonly("saturation",
                             [](const CompiledResult& r) { return r.compiled.saturation; })
      .def_property_readonly("fresnel_nonnegative",
                             [](const CompiledResult& r) { return r.compiled.fresnel_nonnegative; })
      .def_property_readonly(
          "diagnostics", [](const CompiledResult& r) { return diagnostic_list(r.diagnostics); },
          "Warnings and notes, as matc prints them")
      .def("fresnel", &fresnel, py::arg("mu"),
           "F(mu) = max(0, sum c_i b_i(mu)) as the shaders compute it (the shaders' polynomial "
           "basis); for a coated material both lobes' sum")
      .def("exact", &exact, py::arg("mu"),
           "The exact curve the coefficients were fitted to; for a coated material the exact "
           "layered reflectance")
      .def("schlick", &schlick, py::arg("mu"), "Schlick's curve with the exact F0")
      .def("fbar", &fbar, py::arg("ndotv"), py::arg("roughness"), py::arg("table") = nullptr,
           "The preintegrated Fresnel sum c_i bbar_i(NdotV, roughness), one table fetch as a "
           "renderer does (table: matc's default for the basis unless given)")
      .def("fbar_reference", &fbar_reference, py::arg("ndotv"), py::arg("roughness"),
           py::arg("samples") = kReferenceSamples,
           "The exact split-sum integral of the exact curve (Monte Carlo, no basis or table)")
      .def(
          "to_dict",
          [](const CompiledResult& r) {
            const std::string text =
                format_json(compiled_material_json(r.compiled, runtime::shipped_basis(r.basis)));
            return py::module_::import("json").attr("loads")(text);
          },
          "What <name>.json holds (less the inputs hash, which depends on the build's options)")
      .def("__repr__", [](const CompiledResult& r) {
        return fmt::format("<matc.CompiledMaterial '{}' basis={} max_error={:.4f}>",
                           r.compiled.material.name, runtime::basis_name(r.basis),
                           worst_channel(r.compiled.accuracy.decomposition.max_abs));
      });
}

}  // namespace matc::python
