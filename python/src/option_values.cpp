#include "option_values.h"

namespace matc::python {

ShaderLanguage shader_language_from_name(const std::string& name) {
  if (const auto language = matc::shader_language_from_name(name)) return *language;
  throw pybind11::value_error(fmt::format("language: '{}' is not one of glsl, hlsl, wgsl", name));
}

double checked_in_range(std::string_view argument, double value, double low, double high) {
  if (!(value >= low && value <= high))
    throw pybind11::value_error(
        fmt::format("{}: {} is out of range; a number in [{}, {}]", argument, value, low, high));
  return value;
}

std::size_t checked_count(std::string_view argument, std::size_t value, std::size_t low,
                          std::size_t high) {
  if (value < low || value > high)
    throw pybind11::value_error(
        fmt::format("{}: {} is out of range; an integer in [{}, {}]", argument, value, low, high));
  return value;
}

}  // namespace matc::python
