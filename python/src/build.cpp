// matc.Build: the options of one `matc` run and everything it writes, in memory (the public
// API's Build, matc/api/build.h): the shared shader library and tables, each material's shader
// sources and files.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "matc/api/build.h"

namespace py = pybind11;

namespace matc::python {
namespace {

using api::Build;
using BuildPointer = std::shared_ptr<Build>;

BuildPointer make_build(const std::optional<std::vector<std::string>>& emit, std::size_t lut_size,
                        std::size_t lut_samples, const std::string& lut_format,
                        const std::string& lut_precision,
                        const std::string& coefficient_table_precision, std::size_t embed_lut,
                        const std::string& basis, const std::string& color_space,
                        const std::string& gamut_mapping) {
  if (emit && emit->empty())
    throw py::value_error("emit: an empty list; the outputs to write, or None for all");
  api::BuildOptions options;
  if (emit) options.emit = *emit;
  options.lut_size = lut_size;
  options.lut_samples = lut_samples;
  options.lut_format = lut_format;
  options.lut_precision = lut_precision;
  options.coefficient_table_precision = coefficient_table_precision;
  options.embed_lut = embed_lut;
  options.compile = {basis, color_space, gamut_mapping};
  const py::gil_scoped_release release;  // generating the shader library takes a moment
  return std::make_shared<Build>(options);
}

py::dict files_dict(const std::vector<api::OutputFile>& files) {
  py::dict out;
  for (const api::OutputFile& file : files)
    out[py::str(file.name)] = py::bytes(file.bytes);
  return out;
}

py::dict options_dict(const api::BuildOptions& options) {
  py::dict out;
  out["emit"] = py::cast(options.emit);
  out["lut_size"] = options.lut_size;
  out["lut_samples"] = options.lut_samples;
  out["lut_format"] = options.lut_format;
  out["lut_precision"] = options.lut_precision;
  out["coefficient_table_precision"] = options.coefficient_table_precision;
  out["embed_lut"] = options.embed_lut;
  out["basis"] = options.compile.basis;
  out["color_space"] = options.compile.color_space;
  out["gamut_mapping"] = options.compile.gamut_mapping;
  return out;
}

}  // namespace

void register_build(py::module_& module) {
  const api::CompileOptions defaults = api::default_compile_options();
  py::class_<Build, BuildPointer>(
      module, "Build",
      "What one `matc` run writes, with its options (each as the matc option of the same name): "
      "the shared shader library and tables, each material's shaders and files. Thread-safe.")
      .def(py::init(&make_build), py::kw_only(), py::arg("emit") = py::none(),
           py::arg("lut_size") = api::kDefaultLutSize,
           py::arg("lut_samples") = api::kDefaultLutSamples, py::arg("lut_format") = "ktx2",
           py::arg("lut_precision") = "f32", py::arg("coefficient_table_precision") = "f16",
           py::arg("embed_lut") = 0, py::arg("basis") = defaults.basis,
           py::arg("color_space") = defaults.color_space,
           py::arg("gamut_mapping") = defaults.gamut_mapping)
      .def_property_readonly("options", [](const Build& b) { return options_dict(b.options()); })
      .def(
          "_compile",
          [](const Build& b, const api::Material& material) {
            return without_gil([&] { return b.compile(material); });
          },
          py::arg("material"))
      .def(
          "shader",
          [](const Build& b, const api::CompiledMaterial& compiled, const std::string& language) {
            return without_gil([&] { return b.material_source(language, compiled); });
          },
          py::arg("compiled"), py::arg("language"),
          "The material's snippet <name>.<language> ('glsl', 'hlsl' or 'wgsl') as text")
      .def("library", &Build::library_source, py::arg("language"),
           "The shared library matc_fresnel.<language> as text")
      .def(
          "files",
          [](const Build& b, const api::CompiledMaterial& compiled) {
            return files_dict(without_gil([&] { return b.material_files(compiled); }));
          },
          py::arg("compiled"), "The material's own files (name to bytes), as `matc` writes them")
      .def(
          "shared_files",
          [](const Build& b) { return files_dict(without_gil([&] { return b.shared_files(); })); },
          "The shared files (name to bytes): library, tables and their descriptions")
      .def_property_readonly(
          "lut", [](const Build& b) { return without_gil([&] { return b.lut(); }); },
          "The preintegrated table's first layer as matc_lut.* stores it (baked on first use)")
      .def(
          "lut_layer",
          [](const Build& b, const std::string& basis) {
            return without_gil([&] { return b.lut(basis); });
          },
          py::arg("basis"),
          "The preintegrated table's layer of `basis` (a default build holds powers then f82 side "
          "by side in matc_lut.*) as it stores it")
      .def_property_readonly(
          "coefficient_table",
          [](const Build& b) { return without_gil([&] { return b.coefficient_table(); }); },
          "The coefficient table as matc_coefficient_table.* stores it")
      .def(
          "description",
          [](const Build& b) { return py::module_::import("json").attr("loads")(b.description()); },
          "The head of matc_manifest.json: version, inputs hash, options, the tables' files")
      .def("__repr__", [](const Build& b) {
        return fmt::format("<matc.Build basis={} lut_size={} lut_format={}>",
                           b.options().compile.basis, b.options().lut_size, b.options().lut_format);
      });
}

}  // namespace matc::python
