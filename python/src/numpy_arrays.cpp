#include "numpy_arrays.h"

#include <algorithm>

#include <fmt/core.h>

namespace py = pybind11;

namespace matc::python {

void check_unit_interval(std::string_view argument, const DoubleArray& values) {
  const double* data = values.data();
  const std::size_t count = static_cast<std::size_t>(values.size());
  for (std::size_t i = 0; i < count; ++i) {
    if (data[i] >= 0.0 && data[i] <= 1.0) continue;
    throw py::value_error(
        fmt::format("{}: element {} is {}; a number in [0, 1]", argument, i, data[i]));
  }
}

namespace {

// Raises `error` again as the same type, its message prefixed with `what` (the argument).
[[noreturn]] void raise_naming(py::error_already_set& error, std::string_view what) {
  PyObject* type = error.matches(PyExc_MemoryError)  ? PyExc_MemoryError
                   : error.matches(PyExc_TypeError)  ? PyExc_TypeError
                   : error.matches(PyExc_ValueError) ? PyExc_ValueError
                                                     : nullptr;
  if (!type) throw;
  const std::string message =
      fmt::format("{}: {}", what, py::str(error.value()).cast<std::string>());
  PyErr_SetString(type, message.c_str());
  throw py::error_already_set();
}

// numpy.asarray(value, float64, order="C"), checked: pybind11's own conversion answers a failed
// allocation with an empty array (or a TypeError), which is how a large broadcast crashed.
// (Not ascontiguousarray, which makes a 0-d array 1-d.)
DoubleArray contiguous_doubles(const py::handle& value, std::string_view what) {
  try {
    py::object array = py::module_::import("numpy").attr("asarray")(
        value, py::arg("dtype") = "float64", py::arg("order") = "C");
    return DoubleArray::ensure(array);
  } catch (py::error_already_set& error) {
    raise_naming(error, what);
  }
}

}  // namespace

DoubleArray real_array(const py::handle& value, std::string_view argument) {
  py::object array;
  try {
    array = py::module_::import("numpy").attr("asarray")(value);
  } catch (py::error_already_set& error) {
    raise_naming(error, argument);
  }
  const py::object dtype = array.attr("dtype");
  const std::string kind = dtype.attr("kind").cast<std::string>();
  if (kind == "c") {
    throw py::type_error(fmt::format(
        "{}: complex numbers; real numbers (the imaginary part would be dropped)", argument));
  }
  if (kind != "b" && kind != "i" && kind != "u" && kind != "f") {
    throw py::type_error(fmt::format("{}: an array of {}; real numbers", argument,
                                     py::str(dtype).cast<std::string>()));
  }
  return contiguous_doubles(array, argument);
}

std::pair<DoubleArray, DoubleArray> broadcast(const DoubleArray& a, std::string_view a_name,
                                              const DoubleArray& b, std::string_view b_name) {
  if (a.ndim() == b.ndim() && std::equal(a.shape(), a.shape() + a.ndim(), b.shape())) return {a, b};
  const std::string both = fmt::format("{} and {}", a_name, b_name);
  py::tuple views;
  try {
    views = py::module_::import("numpy").attr("broadcast_arrays")(a, b);
  } catch (py::error_already_set& error) {
    raise_naming(error, both);
  }
  return {contiguous_doubles(views[0], both), contiguous_doubles(views[1], both)};
}

std::vector<py::ssize_t> shape_with_axis(const DoubleArray& values, std::size_t width) {
  std::vector<py::ssize_t> shape(values.shape(), values.shape() + values.ndim());
  shape.push_back(static_cast<py::ssize_t>(width));
  return shape;
}

DoubleArray unit_interval_array(const py::handle& value, std::string_view argument) {
  DoubleArray values = real_array(value, argument);
  check_unit_interval(argument, values);
  return values;
}

std::pair<DoubleArray, DoubleArray> ndotv_roughness_pair(const py::handle& ndotv,
                                                         const py::handle& roughness) {
  const DoubleArray checked_ndotv = unit_interval_array(ndotv, "ndotv");
  const DoubleArray checked_roughness = unit_interval_array(roughness, "roughness");
  return broadcast(checked_ndotv, "ndotv", checked_roughness, "roughness");
}

}  // namespace matc::python
