// Which shipped basis a material is compiled against (docs/accuracy.md, "A basis per material").
#pragma once

#include <string_view>

#include "matc/runtime/basis.h"
#include "material/material.h"

namespace matc {

// A build's choice: each material its own among runtime::kPerMaterialBases (`--basis auto`, the
// default), or one basis forced on every material (`--basis NAME`).
struct BasisChoice {
  runtime::BasisKind forced = runtime::kDefaultBasis;  // also the first layer's under auto
  bool per_material = true;

  bool operator==(const BasisChoice&) const = default;
};

// "auto": the per-material choice's name, beside the shipped bases' (`--basis`).
inline constexpr std::string_view kPerMaterialBasisName = "auto";

// The per-material rule. A basis the material pins wins. Otherwise a bare F82-tint metal takes
// `f82`, whose span holds every F82-tint curve (Schlick's is tint 1) exactly; every other curve
// (measured, complex index, Gulbrandsen, coated, filmed) takes `powers`, fitted to the measured
// metals. bench/accuracy/basis_choice_study.cpp measures the rule against the best basis per curve.
runtime::BasisKind per_material_basis(const Material& material);

// The basis `choice` gives `material`.
runtime::BasisKind chosen_basis(const Material& material, const BasisChoice& choice);

}  // namespace matc
