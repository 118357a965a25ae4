#include "matc/runtime/analytic_lut.h"

#include <algorithm>
#include <cmath>

namespace matc::runtime {

// Defined by the generated tables (src/<basis>_analytic_lut_table.cpp).
const AnalyticLutCoefficients& extended_analytic_lut();
const AnalyticLutCoefficients& paper_analytic_lut();
const AnalyticLutCoefficients& f82_analytic_lut();
const AnalyticLutCoefficients& powers_analytic_lut();

const AnalyticLutCoefficients& shipped_analytic_lut(BasisKind kind) {
  switch (kind) {
    case BasisKind::paper:
      return paper_analytic_lut();
    case BasisKind::f82:
      return f82_analytic_lut();
    case BasisKind::powers:
      return powers_analytic_lut();
    case BasisKind::extended:
      break;
  }
  return extended_analytic_lut();
}

std::array<double, 2> analytic_lut_coordinates(double ndotv, double roughness) {
  const double u = std::max(std::sqrt(std::clamp(ndotv, 0.0, 1.0)), kAnalyticLutMinU);
  const double r = std::clamp(roughness, 0.0, 1.0);
  const double a = u * std::sqrt(u);
  const double b = r * std::sqrt(r);
  return {std::sqrt(2.0 * (u * u + r * r)) - 1.0, 2.0 * a / (a + b) - 1.0};
}

std::array<double, kAnalyticLutTerms> analytic_lut_chebyshev(double x) {
  static_assert(kAnalyticLutTerms == 12, "three blocks of four, as the shaders compute them");
  std::array<double, kAnalyticLutTerms> t{};
  t[0] = 1.0;
  t[1] = x;
  t[2] = 2.0 * x * x - 1.0;
  t[3] = 2.0 * x * t[2] - x;
  for (std::size_t base : {4u, 8u}) {
    t[base] = 2.0 * t[base / 2] * t[base / 2] - 1.0;  // T_2n = 2 T_n^2 - 1
    for (std::size_t k = 1; k < 4; ++k)
      t[base + k] = 2.0 * t[base] * t[k] - t[base - k];  // T_(m+k) = 2 T_m T_k - T_(m-k)
  }
  return t;
}

std::array<double, kBasisSize> preintegrated_basis_analytic(
    const AnalyticLutCoefficients& coefficients, double ndotv, double roughness) {
  const auto [x, y] = analytic_lut_coordinates(ndotv, roughness);
  const auto tx = analytic_lut_chebyshev(x);
  const auto ty = analytic_lut_chebyshev(y);
  std::array<double, kBasisSize> bbar{};
  for (std::size_t i = 0; i < kBasisSize; ++i) {
    for (std::size_t p = 0; p < kAnalyticLutTerms; ++p) {
      double row = 0.0;
      for (std::size_t q = 0; q < kAnalyticLutTerms; ++q)
        row += coefficients[i][p][q] * ty[q];
      bbar[i] += tx[p] * row;
    }
  }
  return bbar;
}

Rgb evaluate_fbar_analytic(const Coefficients& coefficients,
                           const AnalyticLutCoefficients& analytic, double ndotv,
                           double roughness) {
  return combine(coefficients, preintegrated_basis_analytic(analytic, ndotv, roughness));
}

}  // namespace matc::runtime
