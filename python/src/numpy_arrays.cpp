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

std::pair<DoubleArray, DoubleArray> broadcast(const DoubleArray& a, const DoubleArray& b) {
  if (a.ndim() == b.ndim() && std::equal(a.shape(), a.shape() + a.ndim(), b.shape())) return {a, b};
  const py::tuple pair = py::module_::import("numpy").attr("broadcast_arrays")(a, b);
  return {DoubleArray::ensure(pair[0]), DoubleArray::ensure(pair[1])};
}

std::vector<py::ssize_t> shape_with_axis(const DoubleArray& values, std::size_t width) {
  std::vector<py::ssize_t> shape(values.shape(), values.shape() + values.ndim());
  shape.push_back(static_cast<py::ssize_t>(width));
  return shape;
}

}  // namespace matc::python
