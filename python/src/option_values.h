// Option text from Python to typed values through the option registry (matc/options/
// option_names.h): a name it does not hold raises ValueError naming the argument and every
// allowed name, as the CLI's errors do.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <pybind11/pybind11.h>

#include "matc/options/option_names.h"
#include "matc/spirv/shader_language.h"

namespace matc::python {

template <typename Value>
Value option_from_name(std::string_view argument, const std::string& name) {
  if (const auto value = option_value<Value>(name)) return *value;
  throw pybind11::value_error(fmt::format("{}: '{}' is not one of {}", argument, name,
                                          fmt::join(option_name_list<Value>(), ", ")));
}

// "glsl", "hlsl" or "wgsl".
ShaderLanguage shader_language_from_name(const std::string& name);

// A value in [low, high] (NaN refused), or ValueError naming the argument and the range.
double checked_in_range(std::string_view argument, double value, double low, double high);
// A count in [low, high], or ValueError naming the argument and the range.
std::size_t checked_count(std::string_view argument, std::size_t value, std::size_t low,
                          std::size_t high);

}  // namespace matc::python
