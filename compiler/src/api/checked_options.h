// The public face's option names as the library's values, or std::invalid_argument naming the
// option and every name it takes; and a compiled material checked against the options of the
// outputs asked of it.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "base/echoed_text.h"
#include "compile/basis_choice.h"
#include "compile/compile.h"
#include "emit/build_options.h"
#include "matc/api/compiled_material.h"
#include "matc/runtime/basis.h"
#include "options/option_names.h"
#include "spirv/shader_language.h"

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

// The build's choice (`auto` or a basis forced on every material), and the basis it gives one
// material (compile/basis_choice.h).
inline BasisChoice basis_choice_of(const CompileOptions& options) {
  return option_from_name("basis", options.basis, BasisChoice{});
}
inline runtime::BasisKind basis_for(const matc::Material& material, const CompileOptions& options) {
  return chosen_basis(material, basis_choice_of(options));
}

inline ColorOptions color_options_of(const CompileOptions& options) {
  return {option_from_name("color_space", options.color_space, kDefaultColorSpace),
          option_from_name("gamut_mapping", options.gamut_mapping, GamutMapping::none)};
}

inline ShaderLanguage language_of(std::string_view name) {
  if (const auto language = shader_language_from_name(name)) return *language;
  throw std::invalid_argument(
      fmt::format("language: '{}' is not one of glsl, hlsl, wgsl", echoed(name)));
}

inline std::string color_key_of(const ColorOptions& color) {
  return fmt::format("{} {}", color_space_name(color.working_space),
                     gamut_mapping_name(color.gamut_mapping));
}

// A material's texts name its basis and colour options: the outputs must share them.
inline void check_same_options(const CompiledMaterial& compiled, const std::string& basis,
                               const std::string& color_key) {
  const std::string compiled_color = color_key_of(compiled.value().color);
  if (compiled.basis() != basis || compiled_color != color_key) {
    throw std::invalid_argument(fmt::format(
        "compiled: {} is compiled with basis {} and colour {}; these outputs are for basis {} "
        "and colour {}: compile it with the outputs' options (a Build's compile())",
        echoed(compiled.name()), compiled.basis(), compiled_color, basis, color_key));
  }
}

// The basis name a build of basis option `basis_option` ("auto" or a basis) gives `compiled`.
inline std::string expected_basis(const CompiledMaterial& compiled,
                                  const std::string& basis_option) {
  return std::string(runtime::basis_name(
      chosen_basis(compiled.value().material, basis_choice_of({basis_option, {}, {}}))));
}

// The same against a build's options.
inline void check_same_options(const CompiledMaterial& compiled, const matc::BuildOptions& build) {
  check_same_options(compiled,
                     std::string(runtime::basis_name(chosen_basis(
                         compiled.value().material, {build.basis, build.per_material_basis}))),
                     color_key_of(build.color));
}

}  // namespace matc::api
