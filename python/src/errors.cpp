#include "errors.h"

#include "bindings.h"

namespace py = pybind11;

namespace matc::python {

py::str python_text(std::string_view text) {
  PyObject* decoded =
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "surrogateescape");
  if (!decoded) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(decoded);
}

std::string formatted_lines(const std::vector<api::Diagnostic>& diagnostics) {
  std::string text;
  for (const api::Diagnostic& diagnostic : diagnostics) {
    if (!text.empty()) text += '\n';
    text += diagnostic.text;
  }
  return text;
}

py::list diagnostic_list(const std::vector<api::Diagnostic>& diagnostics) {
  py::list list;
  for (const api::Diagnostic& diagnostic : diagnostics)
    list.append(py::cast(diagnostic));
  return list;
}

void raise_batch_error(const std::vector<api::Diagnostic>& diagnostics, py::object result) {
  const py::object type = py::module_::import("matc.errors").attr("BatchError");
  const py::object error =
      type(python_text(formatted_lines(diagnostics)), diagnostic_list(diagnostics), result);
  PyErr_SetObject(type.ptr(), error.ptr());
  throw py::error_already_set();
}

void register_errors(py::module_& module) {
  using api::Diagnostic;
  // The public API escapes every part that came from an input: printable, never raw bytes.
  py::class_<Diagnostic>(module, "Diagnostic",
                         "One located message: path:line:column: severity: field: message; "
                         "allowed (line 0: the whole file).")
      .def_readonly("severity", &Diagnostic::severity)
      .def_property_readonly("path", [](const Diagnostic& d) { return python_text(d.path); })
      .def_readonly("line", &Diagnostic::line)
      .def_readonly("column", &Diagnostic::column)
      .def_readonly("field", &Diagnostic::field,
                    "Dotted field path, such as ior.n[1]; may be empty")
      .def_readonly("message", &Diagnostic::message, "What is wrong")
      .def_readonly("allowed", &Diagnostic::allowed, "What would be accepted; may be empty")
      .def("__str__", [](const Diagnostic& d) { return d.text; })
      .def("__repr__", [](const Diagnostic& d) { return "<matc.Diagnostic " + d.text + ">"; });

  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const api::MaterialError& error) {
      const py::object type = py::module_::import("matc.errors").attr("MaterialError");
      const py::object instance =
          type(python_text(error.what()), diagnostic_list(error.diagnostics()));
      PyErr_SetObject(type.ptr(), instance.ptr());
    }
  });
}

}  // namespace matc::python
