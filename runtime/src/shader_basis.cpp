#include "matc/runtime/shader_basis.h"

#include "matc/runtime/powers_basis.h"

namespace matc::runtime {

std::array<double, kBasisSize> evaluate_shader_basis(const ShaderBasis& basis, double mu) {
  if (basis.form == ShaderBasisForm::powers) return evaluate_powers_basis(mu);
  return evaluate_basis_polynomial(basis.polynomial, mu);
}

const ShaderBasis& shipped_shader_basis(BasisKind kind) {
  static const ShaderBasis paper = paper_basis_polynomial();
  static const ShaderBasis extended = extended_basis_polynomial();
  static const ShaderBasis f82 = f82_basis_polynomial();
  static const ShaderBasis powers = ShaderBasis::powers();
  switch (kind) {
    case BasisKind::paper:
      return paper;
    case BasisKind::f82:
      return f82;
    case BasisKind::powers:
      return powers;
    case BasisKind::extended:
      break;
  }
  return extended;
}

}  // namespace matc::runtime
