#include "matc/runtime/fresnel.h"

#include <cassert>

#include "matc/runtime/powers_basis.h"

namespace matc::runtime {

Rgb evaluate_fresnel(const Coefficients& coefficients, const BasisView& basis, double mu) {
  return combine(coefficients, basis.evaluate(mu));
}

Rgb evaluate_fresnel(const Coefficients& coefficients, const ShaderBasis& basis, double mu) {
  return combine(coefficients, evaluate_shader_basis(basis, mu));
}

namespace {

template <typename EvaluateBasis>
void evaluate_each(const Coefficients& coefficients, std::span<const double> mu,
                   std::span<double> rgb, const EvaluateBasis& evaluate_basis) {
  for (std::size_t i = 0; i < mu.size(); ++i) {
    const Rgb value = combine(coefficients, evaluate_basis(mu[i]));
    for (std::size_t c = 0; c < 3; ++c)
      rgb[3 * i + c] = value[c];
  }
}

}  // namespace

void evaluate_fresnel(const Coefficients& coefficients, const ShaderBasis& basis,
                      std::span<const double> mu, std::span<double> rgb) {
  assert(rgb.size() == 3 * mu.size());
  if (basis.form == ShaderBasisForm::powers) {
    evaluate_each(coefficients, mu, rgb,
                  [](double cosine) { return evaluate_powers_basis(cosine); });
  } else if (basis.form == ShaderBasisForm::f82) {
    evaluate_each(coefficients, mu, rgb, [](double cosine) { return evaluate_f82_basis(cosine); });
  } else {
    evaluate_each(coefficients, mu, rgb, [&](double cosine) {
      return evaluate_basis_polynomial(basis.polynomial, cosine);
    });
  }
}

}  // namespace matc::runtime
