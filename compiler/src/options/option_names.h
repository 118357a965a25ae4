// The one registry of the names that options take: for each kind of value (output kinds, table
// formats and precisions, bases, colour spaces, gamut mappings, LTC objectives) every name and the
// value it stands for. Each name is spelled once, by the module that owns the value
// (output_kind_name, lut_format_name, basis_name, ...); this is the one place where option text
// becomes a typed value, at the edge: the CLI reads it, and nothing below it looks a name up.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compile/basis_choice.h"
#include "emit/output_layout.h"
#include "formats/table_format.h"
#include "ltc/ltc_fit.h"
#include "matc/runtime/basis.h"
#include "optics/color_space.h"
#include "optics/gamut.h"

namespace matc {

template <typename Value>
struct OptionName {
  std::string_view name;
  Value value;
};

// Every value of the kind with its name, in the order help and errors list them.
template <typename Value>
std::span<const OptionName<Value>> option_names();
template <>
std::span<const OptionName<OutputKind>> option_names<OutputKind>();
template <>
std::span<const OptionName<LutFormat>> option_names<LutFormat>();
template <>
std::span<const OptionName<LutPrecision>> option_names<LutPrecision>();
template <>
std::span<const OptionName<runtime::BasisKind>> option_names<runtime::BasisKind>();
// A build's basis: "auto" (a basis per material), then every shipped basis forced.
template <>
std::span<const OptionName<BasisChoice>> option_names<BasisChoice>();
template <>
std::span<const OptionName<ColorSpace>> option_names<ColorSpace>();
template <>
std::span<const OptionName<GamutMapping>> option_names<GamutMapping>();
template <>
std::span<const OptionName<LtcObjective>> option_names<LtcObjective>();

// The value `name` stands for (colour spaces also take their aliases, such as lin_srgb).
template <typename Value>
std::optional<Value> option_value(std::string_view name) {
  for (const OptionName<Value>& entry : option_names<Value>())
    if (entry.name == name) return entry.value;
  return std::nullopt;
}
template <>
std::optional<ColorSpace> option_value<ColorSpace>(std::string_view name);

template <typename Value>
std::string_view option_name(Value value) {
  for (const OptionName<Value>& entry : option_names<Value>())
    if (entry.value == value) return entry.name;
  return {};
}

// The names alone, in order (for help texts, CLI11's IsMember and errors).
template <typename Value>
std::vector<std::string> option_name_list() {
  std::vector<std::string> names;
  for (const OptionName<Value>& entry : option_names<Value>())
    names.emplace_back(entry.name);
  return names;
}

}  // namespace matc
