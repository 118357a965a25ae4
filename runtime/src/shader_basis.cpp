#include "matc/runtime/shader_basis.h"

#include "matc/runtime/powers_basis.h"
#include "matc/runtime/shipped_bases.h"

namespace matc::runtime {

std::array<double, kBasisSize> evaluate_shader_basis(const ShaderBasis& basis, double mu) {
  switch (basis.form) {
    case ShaderBasisForm::powers:
      return evaluate_powers_basis(mu);
    case ShaderBasisForm::f82:
      return evaluate_f82_basis(mu);
    case ShaderBasisForm::piecewise_polynomial:
      break;
  }
  return evaluate_basis_polynomial(basis.polynomial, mu);
}

const ShaderBasis& shipped_shader_basis(BasisKind kind) {
  // Built once: a fitted basis' form holds its polynomial's coefficients.
  static const std::array<ShaderBasis, kShippedBases.size()> forms = [] {
    std::array<ShaderBasis, kShippedBases.size()> built;
    for (std::size_t i = 0; i < built.size(); ++i)
      built[i] = shipped_basis_records()[i].shader_form();
    return built;
  }();
  return forms[static_cast<std::size_t>(&shipped_basis_record(kind) -
                                        shipped_basis_records().data())];
}

}  // namespace matc::runtime
