// matc.Build: the options of one `matc` run and everything it writes, in memory: the shared
// shader library and tables, each material's shader sources and files.
#include "matc/emit/build.h"

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.h"
#include "compiled_material.h"
#include "matc/base/json_format.h"
#include "matc/optics/color_space.h"
#include "numpy_arrays.h"
#include "option_values.h"
#include "tables.h"

namespace py = pybind11;

namespace matc::python {
namespace {

using BuildPointer = std::shared_ptr<Build>;

BuildPointer make_build(const std::optional<std::vector<std::string>>& emit, std::size_t lut_size,
                        std::size_t lut_samples, const std::string& lut_format,
                        const std::string& lut_precision,
                        const std::string& coefficient_table_precision, std::size_t embed_lut,
                        const std::string& basis, const std::string& color_space,
                        const std::string& gamut_mapping) {
  // The CLI's ranges for its --lut-size, --lut-samples and --embed-lut-size.
  checked_count("lut_size", lut_size, kMinLutSize, kMaxLutSize);
  checked_count("lut_samples", lut_samples, 1, kMaxLutSamples);
  if (embed_lut != 0) checked_count("embed_lut", embed_lut, 2, kMaxEmbeddedLutSize);
  BuildOptions options;
  if (emit) {
    options.emit.clear();
    for (const std::string& kind : *emit)
      options.emit.insert(option_from_name<OutputKind>("emit", kind));
  }
  options.lut.size = lut_size;
  options.lut.samples = lut_samples;
  options.lut_format = option_from_name<LutFormat>("lut_format", lut_format);
  options.lut_precision = option_from_name<LutPrecision>("lut_precision", lut_precision);
  options.coefficient_table_precision =
      option_from_name<LutPrecision>("coefficient_table_precision", coefficient_table_precision);
  options.embedded_lut_size = embed_lut;
  options.basis = option_from_name<runtime::BasisKind>("basis", basis);
  options.color.working_space = option_from_name<ColorSpace>("color_space", color_space);
  options.color.gamut_mapping = option_from_name<GamutMapping>("gamut_mapping", gamut_mapping);
  py::gil_scoped_release release;  // generating the shader library takes a moment
  return std::make_shared<Build>(std::move(options));
}

py::dict files_dict(const std::vector<OutputFile>& files) {
  py::dict out;
  for (const OutputFile& file : files)
    out[py::str(file.name)] = py::bytes(file.bytes);
  return out;
}

const CompiledMaterial& compiled_for(const Build& build, const CompiledResult& result) {
  if (result.basis != build.options().basis ||
      result.compiled.color.working_space != build.options().color.working_space ||
      result.compiled.color.gamut_mapping != build.options().color.gamut_mapping) {
    throw py::value_error(fmt::format(
        "compiled: '{}' was compiled with basis {}, colour space {}; this build uses {}, {}: "
        "compile it with this build's compile()",
        result.compiled.material.name, runtime::basis_name(result.basis),
        color_space_name(result.compiled.color.working_space),
        runtime::basis_name(build.options().basis),
        color_space_name(build.options().color.working_space)));
  }
  return result.compiled;
}

py::dict options_dict(const BuildOptions& options) {
  py::list emit;
  for (const OutputKind kind : options.emit)
    emit.append(std::string(output_kind_name(kind)));
  py::dict out;
  out["emit"] = emit;
  out["lut_size"] = options.lut.size;
  out["lut_samples"] = options.lut.samples;
  out["lut_format"] = std::string(lut_format_name(options.lut_format));
  out["lut_precision"] = std::string(lut_precision_name(options.lut_precision));
  out["coefficient_table_precision"] =
      std::string(lut_precision_name(options.coefficient_table_precision));
  out["embed_lut"] = options.embedded_lut_size;
  out["basis"] = std::string(runtime::basis_name(options.basis));
  out["color_space"] = std::string(color_space_name(options.color.working_space));
  out["gamut_mapping"] = std::string(gamut_mapping_name(options.color.gamut_mapping));
  return out;
}

}  // namespace

void register_build(py::module_& module) {
  py::class_<Build, BuildPointer>(
      module, "Build",
      "What one `matc` run writes, with its options (each as the matc option of the same name): "
      "the shared shader library and tables, each material's shaders and files. Thread-safe.")
      .def(py::init(&make_build), py::kw_only(), py::arg("emit") = py::none(),
           py::arg("lut_size") = kDefaultLutSize, py::arg("lut_samples") = kDefaultLutSamples,
           py::arg("lut_format") = "ktx2", py::arg("lut_precision") = "f32",
           py::arg("coefficient_table_precision") = "f16", py::arg("embed_lut") = 0,
           py::arg("basis") = std::string(runtime::basis_name(runtime::kDefaultBasis)),
           py::arg("color_space") = std::string(color_space_name(kDefaultColorSpace)),
           py::arg("gamut_mapping") = "none")
      .def_property_readonly("options", [](const Build& b) { return options_dict(b.options()); })
      .def(
          "_compile",
          [](const Build& b, const LoadedMaterialPointer& material) {
            return compile_loaded(material, b.options().basis, b.options().color);
          },
          py::arg("material"))
      .def(
          "shader",
          [](const Build& b, const CompiledResult& compiled, const std::string& language) {
            const ShaderLanguage chosen = shader_language_from_name(language);
            const CompiledMaterial& material = compiled_for(b, compiled);
            py::gil_scoped_release release;
            return b.material_source(chosen, material);
          },
          py::arg("compiled"), py::arg("language"),
          "The material's snippet <name>.<language> ('glsl', 'hlsl' or 'wgsl') as text")
      .def(
          "library",
          [](const Build& b, const std::string& language) {
            return b.library_source(shader_language_from_name(language));
          },
          py::arg("language"), "The shared library matc_fresnel.<language> as text")
      .def(
          "files",
          [](const Build& b, const CompiledResult& compiled) {
            const CompiledMaterial& material = compiled_for(b, compiled);
            MaterialOutputs outputs;
            {
              py::gil_scoped_release release;
              outputs = b.material_outputs(material);
            }
            return files_dict(outputs.files);
          },
          py::arg("compiled"), "The material's own files (name to bytes), as `matc` writes them")
      .def(
          "shared_files",
          [](const Build& b) {
            std::vector<OutputFile> files;
            {
              py::gil_scoped_release release;
              files = b.shared_outputs();
            }
            return files_dict(files);
          },
          "The shared files (name to bytes): library, tables and their descriptions")
      .def_property_readonly(
          "lut",
          [](const Build& b) {
            Lut stored;
            {
              py::gil_scoped_release release;
              stored = b.stored_lut();
            }
            return PreintegratedTable{std::make_shared<const Lut>(std::move(stored)),
                                      b.options().basis, b.options().lut_precision};
          },
          "The preintegrated table as matc_lut.* stores it (baked on first use)")
      .def_property_readonly(
          "coefficient_table",
          [](const Build& b) {
            return CoefficientTableObject{
                std::make_shared<const CoefficientTable>(b.stored_coefficient_table()),
                b.options().coefficient_table_precision};
          },
          "The coefficient table as matc_coefficient_table.* stores it")
      .def(
          "description",
          [](const Build& b) {
            return py::module_::import("json").attr("loads")(format_json(b.description()));
          },
          "The head of matc_manifest.json: version, inputs hash, options, the tables' files")
      .def("__repr__", [](const Build& b) {
        return fmt::format("<matc.Build basis={} lut_size={} lut_format={}>",
                           runtime::basis_name(b.options().basis), b.options().lut.size,
                           lut_format_name(b.options().lut_format));
      });
}

}  // namespace matc::python
