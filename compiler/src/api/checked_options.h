// The public face's option names as the library's values, or std::invalid_argument naming the
// option and every name it takes.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "matc/api/compiled_material.h"
#include "matc/base/echoed_text.h"
#include "matc/compile/compile.h"
#include "matc/options/option_names.h"
#include "matc/runtime/basis.h"

namespace matc::api {

template <typename Value>
Value checked_option_value(std::string_view option, std::string_view name) {
  if (const auto value = option_value<Value>(name)) return *value;
  throw std::invalid_argument(fmt::format("{}: '{}' is not one of {}", option, echoed(name),
                                          fmt::join(option_name_list<Value>(), ", ")));
}

// The same where an empty name means `default_value`.
template <typename Value>
Value option_from_name(std::string_view option, std::string_view name, Value default_value) {
  return name.empty() ? default_value : checked_option_value<Value>(option, name);
}

inline runtime::BasisKind basis_of(const CompileOptions& options) {
  return option_from_name("basis", options.basis, runtime::kDefaultBasis);
}

inline ColorOptions color_options_of(const CompileOptions& options) {
  return {option_from_name("color_space", options.color_space, kDefaultColorSpace),
          option_from_name("gamut_mapping", options.gamut_mapping, GamutMapping::none)};
}

}  // namespace matc::api
