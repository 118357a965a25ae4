#include "material/basis_pin.h"

#include <fmt/format.h>

#include "base/echoed_text.h"

namespace matc {

std::string basis_pin_rule() {
  return fmt::format(
      "one of {} (the bases a per-material build's table holds; the fitted bases serve whole "
      "builds: --basis NAME)",
      runtime::per_material_basis_names());
}

BasisPin read_basis_pin(std::string_view name, std::string_view layered) {
  const auto kind = runtime::basis_from_name(name);
  if (!kind || !runtime::is_per_material_basis(*kind)) {
    return {std::nullopt, BasisPinProblem{kind ? fmt::format("'{}' is a fitted basis", name)
                                               : fmt::format("unknown basis '{}'", echoed(name)),
                                          basis_pin_rule()}};
  }
  if (*kind != runtime::kDefaultBasis && !layered.empty()) {
    return {std::nullopt,
            BasisPinProblem{
                fmt::format("pins '{}' on a metal with a {}", name, layered),
                fmt::format("'{}': a coated or filmed metal takes the build's first basis; drop "
                            "the pin, or force one basis on the whole build with --basis {}",
                            runtime::basis_name(runtime::kDefaultBasis), name)}};
  }
  return {kind, std::nullopt};
}

}  // namespace matc
