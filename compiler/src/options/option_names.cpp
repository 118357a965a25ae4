#include "options/option_names.h"

#include <vector>

namespace matc {
namespace {

// The registry's entries of one kind: `values` in order, each named by its owner's `name_of`.
template <typename Value, typename Values, typename NameOf>
std::vector<OptionName<Value>> named(const Values& values, NameOf name_of) {
  std::vector<OptionName<Value>> entries;
  for (const Value value : values)
    entries.push_back({name_of(value), value});
  return entries;
}

std::vector<OutputKind> layout_kinds() {
  std::vector<OutputKind> kinds;
  for (const OutputKindLayout& layout : output_layout())
    kinds.push_back(layout.kind);
  return kinds;
}

std::vector<ColorSpace> defined_color_spaces() {
  std::vector<ColorSpace> spaces;
  for (const ColorSpaceDefinition& definition : color_spaces())
    spaces.push_back(definition.id);
  return spaces;
}

}  // namespace

template <>
std::span<const OptionName<OutputKind>> option_names<OutputKind>() {
  static const auto entries = named<OutputKind>(layout_kinds(), output_kind_name);
  return entries;
}

template <>
std::span<const OptionName<LutFormat>> option_names<LutFormat>() {
  static const auto entries = named<LutFormat>(kLutFormats, lut_format_name);
  return entries;
}

template <>
std::span<const OptionName<LutPrecision>> option_names<LutPrecision>() {
  static const auto entries = named<LutPrecision>(kLutPrecisions, lut_precision_name);
  return entries;
}

template <>
std::span<const OptionName<runtime::BasisKind>> option_names<runtime::BasisKind>() {
  static const auto entries =
      named<runtime::BasisKind>(runtime::kShippedBases, runtime::basis_name);
  return entries;
}

template <>
std::span<const OptionName<BasisChoice>> option_names<BasisChoice>() {
  static const auto entries = [] {
    std::vector<OptionName<BasisChoice>> list = {
        {kPerMaterialBasisName, {runtime::kPerMaterialBases.front(), true}}};
    for (const runtime::BasisKind kind : runtime::kShippedBases)
      list.push_back({runtime::basis_name(kind), {kind, false}});
    return list;
  }();
  return entries;
}

template <>
std::span<const OptionName<ColorSpace>> option_names<ColorSpace>() {
  static const auto entries = named<ColorSpace>(defined_color_spaces(), color_space_name);
  return entries;
}

template <>
std::span<const OptionName<GamutMapping>> option_names<GamutMapping>() {
  static const auto entries = named<GamutMapping>(kGamutMappings, gamut_mapping_name);
  return entries;
}

template <>
std::span<const OptionName<LtcObjective>> option_names<LtcObjective>() {
  static const auto entries = named<LtcObjective>(kLtcObjectives, ltc_objective_name);
  return entries;
}

template <>
std::optional<ColorSpace> option_value<ColorSpace>(std::string_view name) {
  return find_color_space(name);  // the spaces' names and the aliases the optics module accepts
}

}  // namespace matc
