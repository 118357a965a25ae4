#include "compile/basis_choice.h"

#include <variant>

#include "compile/compile.h"

namespace matc {

runtime::BasisKind per_material_basis(const Material& material) {
  if (material.basis) return *material.basis;
  const bool bare = !material.coat && !has_visible_film(material);
  if (bare && std::holds_alternative<F82TintInput>(material.model)) return runtime::BasisKind::f82;
  return runtime::BasisKind::powers;
}

runtime::BasisKind chosen_basis(const Material& material, const BasisChoice& choice) {
  return choice.per_material ? per_material_basis(material) : choice.forced;
}

}  // namespace matc
