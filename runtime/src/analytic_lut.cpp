#include "matc/runtime/analytic_lut.h"

#include <algorithm>
#include <cmath>

#include "matc/runtime/shader_basis.h"
#include "matc/runtime/shipped_bases.h"

namespace matc::runtime {

const AnalyticLutCoefficients& shipped_analytic_lut(BasisKind kind) {
  return shipped_basis_record(kind).analytic_lut();
}

std::array<double, 2> analytic_lut_coordinates(double ndotv, double roughness) {
  const double u = std::max(std::sqrt(std::clamp(ndotv, 0.0, 1.0)), kAnalyticLutMinU);
  const double r = std::clamp(roughness, 0.0, 1.0);
  const double a = u * std::sqrt(u);
  const double b = r * std::sqrt(r);
  return {std::sqrt(2.0 * (u * u + r * r)) - 1.0, 2.0 * a / (a + b) - 1.0};
}

AnalyticLutChebyshev analytic_lut_chebyshev(double x) {
  AnalyticLutChebyshev t{};
  t[0] = 1.0;
  t[1] = x;
  for (std::size_t k = 2; k < t.size(); ++k)
    t[k] = 2.0 * x * t[k - 1] - t[k - 2];
  return t;
}

double analytic_lut_polynomial(std::span<const double> coefficients, std::size_t degree,
                               const AnalyticLutChebyshev& tx, const AnalyticLutChebyshev& ty) {
  double sum = 0.0;
  std::size_t term = 0;
  for (std::size_t p = 0; p <= degree; ++p) {
    double row = 0.0;
    for (std::size_t q = 0; q + p <= degree; ++q)
      row += coefficients[term++] * ty[q];
    sum += tx[p] * row;
  }
  return sum;
}

AnalyticLutFields analytic_lut_fields(const AnalyticLutCoefficients& coefficients, double ndotv,
                                      double roughness) {
  const auto [x, y] = analytic_lut_coordinates(ndotv, roughness);
  const AnalyticLutChebyshev tx = analytic_lut_chebyshev(x);
  const AnalyticLutChebyshev ty = analytic_lut_chebyshev(y);
  constexpr std::size_t kQuadrature = kAnalyticLutQuadratureDegree;
  return {analytic_lut_polynomial(coefficients.albedo, kAnalyticLutAlbedoDegree, tx, ty),
          analytic_lut_polynomial(coefficients.node_a, kQuadrature, tx, ty),
          analytic_lut_polynomial(coefficients.node_b, kQuadrature, tx, ty),
          analytic_lut_polynomial(coefficients.weight_b, kQuadrature, tx, ty)};
}

std::array<double, kBasisSize> preintegrated_basis_analytic(
    const AnalyticLutCoefficients& coefficients, double ndotv, double roughness) {
  const AnalyticLutFields fields = analytic_lut_fields(coefficients, ndotv, roughness);
  const ShaderBasis& basis = shipped_shader_basis(coefficients.basis);
  const auto at_a = evaluate_shader_basis(basis, fields.node_a);
  const auto at_b = evaluate_shader_basis(basis, fields.node_b);
  // The weight clamped to [0, 1] (the fit keeps it there; the clamp makes Fbar a convex blend of
  // two values of F, so a curve matc proved non-negative gives a non-negative Fbar here too).
  const double t = std::clamp(fields.weight_b, 0.0, 1.0);
  std::array<double, kBasisSize> bbar{};
  for (std::size_t i = 0; i < kBasisSize; ++i)
    bbar[i] = fields.albedo * (at_a[i] + t * (at_b[i] - at_a[i]));
  return bbar;
}

Rgb evaluate_fbar_analytic(const Coefficients& coefficients,
                           const AnalyticLutCoefficients& analytic, double ndotv,
                           double roughness) {
  return combine(coefficients, preintegrated_basis_analytic(analytic, ndotv, roughness));
}

}  // namespace matc::runtime
