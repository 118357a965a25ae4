#include "errors.h"

#include "bindings.h"
#include "matc/base/echoed_text.h"

namespace py = pybind11;

namespace matc::python {

py::str python_text(std::string_view text) {
  PyObject* decoded =
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "surrogateescape");
  if (!decoded) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(decoded);
}

std::string formatted_lines(const Diagnostics& diagnostics) {
  std::string text;
  for (const Diagnostic& diagnostic : diagnostics.items()) {
    if (!text.empty()) text += '\n';
    text += format_diagnostic(diagnostic);
  }
  return text;
}

py::list diagnostic_list(const Diagnostics& diagnostics) {
  py::list list;
  for (const Diagnostic& diagnostic : diagnostics.items())
    list.append(py::cast(diagnostic));
  return list;
}

void raise_batch_error(const Diagnostics& diagnostics, py::object result) {
  const py::object type = py::module_::import("matc.errors").attr("BatchError");
  const py::object error =
      type(python_text(formatted_lines(diagnostics)), diagnostic_list(diagnostics), result);
  PyErr_SetObject(type.ptr(), error.ptr());
  throw py::error_already_set();
}

void register_errors(py::module_& module) {
  py::class_<Diagnostic>(module, "Diagnostic",
                         "One located message: path:line:column: severity: field: message; "
                         "allowed (line 0: the whole file).")
      .def_property_readonly(
          "severity", [](const Diagnostic& d) { return std::string(severity_name(d.severity)); })
      .def_property_readonly("path",
                             [](const Diagnostic& d) { return python_text(d.location.path); })
      .def_property_readonly("line", [](const Diagnostic& d) { return d.location.line; })
      .def_property_readonly("column", [](const Diagnostic& d) { return d.location.column; })
      // As the CLI prints them: input text in them escaped (printable), never raw bytes.
      .def_property_readonly(
          "field", [](const Diagnostic& d) { return printable(d.field); },
          "Dotted field path, such as ior.n[1]; may be empty")
      .def_property_readonly(
          "message", [](const Diagnostic& d) { return printable(d.message); }, "What is wrong")
      .def_property_readonly(
          "allowed", [](const Diagnostic& d) { return printable(d.allowed); },
          "What would be accepted; may be empty")
      .def("__str__", [](const Diagnostic& d) { return format_diagnostic(d); })
      .def("__repr__",
           [](const Diagnostic& d) { return "<matc.Diagnostic " + format_diagnostic(d) + ">"; });

  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const MaterialErrorThrown& error) {
      const py::object type = py::module_::import("matc.errors").attr("MaterialError");
      const py::object instance =
          type(python_text(error.what()), diagnostic_list(error.diagnostics()));
      PyErr_SetObject(type.ptr(), instance.ptr());
    }
  });
}

}  // namespace matc::python
