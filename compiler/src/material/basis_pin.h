// A material's basis pin ("basis" in a material file, `matc_basis` on a MaterialX material or in a
// glTF material's extras): one basis a per-material build's table holds, and the build's first
// basis only on a coated or filmed metal (their shader paths use the first layer's functions).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "matc/runtime/basis.h"

namespace matc {

// The pin's name in the documents matc imports: an attribute of a MaterialX <surfacematerial>, a
// member of a glTF material's "extras".
inline constexpr std::string_view kBasisPinAttribute = "matc_basis";

struct BasisPinProblem {
  std::string problem;  // what is wrong, the pinned name escaped
  std::string allowed;  // what would be right
};

// The basis `name` pins, or why it cannot: `layered` names the metal's "coat" or "film" (empty for
// a bare metal).
struct BasisPin {
  std::optional<runtime::BasisKind> basis;
  std::optional<BasisPinProblem> problem;
};
BasisPin read_basis_pin(std::string_view name, std::string_view layered);

// What a pin may be, as diagnostics word it.
std::string basis_pin_rule();

}  // namespace matc
