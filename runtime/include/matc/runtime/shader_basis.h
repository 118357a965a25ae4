// How the shaders evaluate a basis, and its CPU mirror: the piecewise polynomial of
// basis_polynomial.h (fitted bases), or a closed form of powers_basis.h. Whatever measures
// accuracy or solves coefficients against "the basis as the shaders evaluate it" takes this.
#pragma once

#include <array>

#include "matc/runtime/basis.h"
#include "matc/runtime/basis_polynomial.h"

namespace matc::runtime {

// `powers` and `f82` are the closed forms of the bases of the same names.
enum class ShaderBasisForm { piecewise_polynomial, powers, f82 };

struct ShaderBasis {
  ShaderBasisForm form = ShaderBasisForm::piecewise_polynomial;
  BasisPolynomial polynomial{};  // the piecewise form's coefficients; unused by the closed forms

  ShaderBasis() = default;
  // A fitted basis' polynomial is its shader form.
  ShaderBasis(const BasisPolynomial& fitted) : polynomial(fitted) {}  // NOLINT: implicit on purpose
  static ShaderBasis closed_form(ShaderBasisForm form) {
    ShaderBasis basis;
    basis.form = form;
    return basis;
  }
  static ShaderBasis powers() { return closed_form(ShaderBasisForm::powers); }
  static ShaderBasis f82() { return closed_form(ShaderBasisForm::f82); }
  bool is_closed_form() const { return form != ShaderBasisForm::piecewise_polynomial; }
};

// b_0..b_3 at mu (clamped to [0, 1]), exactly the steps of the shaders' matc_basis().
std::array<double, kBasisSize> evaluate_shader_basis(const ShaderBasis& basis, double mu);

// The shader form of a shipped basis.
const ShaderBasis& shipped_shader_basis(BasisKind kind = kDefaultBasis);

}  // namespace matc::runtime
