#include "matc/api/options.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "base/number_text.h"

#include "options/option_names.h"

namespace matc::api {
namespace {

// calls visit(Value{}) with the option's kind of value, typed.
template <typename Visit>
auto with_option_kind(std::string_view option, const Visit& visit) {
  if (option == "basis") return visit(runtime::kDefaultBasis);
  if (option == "build_basis") return visit(BasisChoice{});
  if (option == "color_space") return visit(kDefaultColorSpace);
  if (option == "gamut_mapping") return visit(GamutMapping::none);
  if (option == "emit") return visit(OutputKind::glsl);
  if (option == "lut_format") return visit(LutFormat::ktx2);
  if (option == "lut_precision") return visit(LutPrecision::f32);
  if (option == "ltc_objective") return visit(LtcObjective::polygons);
  throw std::invalid_argument(
      "option: not one of basis, build_basis, color_space, gamut_mapping, emit, lut_format, "
      "lut_precision, "
      "ltc_objective");
}

}  // namespace

std::vector<std::string> option_names(std::string_view option) {
  return with_option_kind(option, [](auto kind) { return option_name_list<decltype(kind)>(); });
}

std::string option_default(std::string_view option) {
  if (option == "emit") return {};
  return with_option_kind(option, [](auto kind) { return std::string(option_name(kind)); });
}

bool takes_option_name(std::string_view option, std::string_view name) {
  return with_option_kind(
      option, [name](auto kind) { return option_value<decltype(kind)>(name).has_value(); });
}

Rgb parse_channel_values(std::string_view label, std::string_view text, double max) {
  const auto fail = [&](const std::string& problem) {
    return std::invalid_argument(fmt::format(
        "{}: {}; give one value (grey) or three (R,G,B), each in [0, {}], comma-separated", label,
        problem, max));
  };
  std::vector<std::string_view> items;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    items.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  if (items.size() != 1 && items.size() != 3)
    throw fail(fmt::format("{} values given", items.size()));
  Rgb values{};
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::optional<double> value = parse_number(items[i]);
    if (!value) throw fail(fmt::format("'{}' is not a number", echoed(items[i])));
    if (!std::isfinite(*value) || *value < 0.0 || *value > max)
      throw fail(fmt::format("{} is outside [0, {}]", echoed(items[i]), max));
    values[i] = *value;
  }
  if (items.size() == 1) values = {values[0], values[0], values[0]};
  return values;
}

}  // namespace matc::api
