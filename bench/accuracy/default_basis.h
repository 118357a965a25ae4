// The basis a default build (a basis per material, `--basis auto`) gives a bare material of a
// model: the compiler's own rule (compile/basis_choice.h), asked rather than restated, so the
// studies and the accuracy tables score what a build does.
#pragma once

#include <utility>

#include "compile/basis_choice.h"
#include "material/material.h"

namespace matc::bench {

inline runtime::BasisKind default_basis_for(MaterialModel model) {
  Material material;
  material.model = std::move(model);
  return per_material_basis(material);
}

}  // namespace matc::bench
