#include "matc/api/options.h"

#include <stdexcept>

#include "matc/options/option_names.h"

namespace matc::api {
namespace {

// calls visit(Value{}) with the option's kind of value, typed.
template <typename Visit>
auto with_option_kind(std::string_view option, const Visit& visit) {
  if (option == "basis") return visit(runtime::kDefaultBasis);
  if (option == "color_space") return visit(kDefaultColorSpace);
  if (option == "gamut_mapping") return visit(GamutMapping::none);
  if (option == "emit") return visit(OutputKind::glsl);
  if (option == "lut_format") return visit(LutFormat::ktx2);
  if (option == "lut_precision") return visit(LutPrecision::f32);
  throw std::invalid_argument(
      "option: not one of basis, color_space, gamut_mapping, emit, lut_format, lut_precision");
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

}  // namespace matc::api
