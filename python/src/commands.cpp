// What matc's commands give, from Python through the public API: `matc eval`'s evaluation
// (matc.evaluate), `matc basis` (matc.describe_basis) and `matc layout` (matc.output_file_names).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.h"
#include "matc/api/basis.h"
#include "matc/api/evaluation.h"
#include "matc/matc.h"

namespace py = pybind11;

namespace matc::python {
namespace {

py::object json_value(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

py::object evaluate(const api::Material& material, const std::vector<double>& mu,
                    const std::vector<double>& ndotv, const std::vector<double>& roughness,
                    bool reference, const std::optional<std::string>& quad_light,
                    const std::optional<double>& metalness, std::size_t light_samples, std::size_t lut_size, std::size_t lut_samples,
                    const std::string& lut_precision,
                    const std::string& coefficient_table_precision, const std::string& basis,
                    const std::string& color_space, const std::string& gamut_mapping) {
  api::EvaluationOptions options;
  options.mu = mu;
  options.ndotv = ndotv;
  options.roughness = roughness;
  options.reference = reference;
  if (quad_light) options.quad_light = api::parse_quad_light(*quad_light);
  options.metalness = metalness;
  options.light_samples = light_samples;
  options.lut_size = lut_size;
  options.lut_samples = lut_samples;
  options.lut_precision = lut_precision;
  options.coefficient_table_precision = coefficient_table_precision;
  options.compile = {basis, color_space, gamut_mapping};
  return json_value(without_gil([&] { return api::evaluate(material, options); }));
}

py::dict basis_dict(const std::string& name) {
  const api::BasisDescription basis = api::describe_basis(name);
  py::dict out;
  out["name"] = basis.name;
  out["description"] = basis.description;
  out["closed_form"] = basis.closed_form;
  out["mu"] = basis.mu;
  out["b"] = basis.b;
  out["probes"] = basis.probes;
  out["polynomial_error_at_samples"] = basis.polynomial_error_at_samples;
  out["polynomial_error_between_samples"] = basis.polynomial_error_between_samples;
  return out;
}

}  // namespace

void register_commands(py::module_& module) {
  const api::CompileOptions defaults = api::default_compile_options();
  module.def("_evaluate", &evaluate, py::arg("material"), py::arg("mu"), py::arg("ndotv"),
             py::arg("roughness"), py::arg("reference"), py::arg("quad_light"), py::arg("metalness"),
             py::arg("light_samples") = api::kDefaultLightSamples,
             py::arg("lut_size") = api::kDefaultLutSize,
             py::arg("lut_samples") = api::kDefaultLutSamples, py::arg("lut_precision") = "f32",
             py::arg("coefficient_table_precision") = "f16", py::arg("basis") = defaults.basis,
             py::arg("color_space") = defaults.color_space,
             py::arg("gamut_mapping") = defaults.gamut_mapping);
  module.def("describe_basis", &basis_dict, py::arg("basis") = api::option_default("basis"),
             "A shipped basis as `matc basis` shows it: its samples (mu, b_0..b_3), probes, and "
             "its shader polynomials' error against the table");
  module.def(
      "output_file_names",
      [](const std::vector<std::string>& names, const std::optional<std::vector<std::string>>& emit,
         const std::string& lut_format, bool no_shared, bool shared_only) {
        api::LayoutOptions options;
        if (emit) options.emit = *emit;
        options.lut_format = lut_format;
        options.no_shared = no_shared;
        options.shared_only = shared_only;
        return api::output_file_names(names, options);
      },
      py::arg("names"), py::kw_only(), py::arg("emit") = py::none(), py::arg("lut_format") = "ktx2",
      py::arg("no_shared") = false, py::arg("shared_only") = false,
      "The files a compile of materials with these names writes, named before it runs (what "
      "`matc layout` prints)");
}

}  // namespace matc::python
