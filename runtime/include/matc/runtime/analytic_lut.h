// The preintegrated table in closed form, for shaders that cannot bind a texture (issue #20,
// docs/lut.md "A closed form"), written so that it costs a third of the two-dimensional
// polynomials it replaced (issue #28):
//     bbar(NdotV, roughness) = E ((1 - t) b(mu_a) + t b(mu_b))
// E is the GGX lobe's directional albedo (bbar_0), and mu_a, mu_b, t a two-point quadrature of the
// basis b over the lobe's distribution of VdotH: nodes mu_a, mu_b and the weight t of the second
// (clamped to [0, 1], so that Fbar is a convex blend of two values of F).
// Each of the four is one polynomial, fitted by `matc basis analytic-lut` to the baked 128x128
// table of each shipped basis, in Chebyshev form, of total degree 12 (E) or 6 (the quadrature),
// in polar coordinates about the mirror-grazing corner:
//     u = max(sqrt(NdotV), 0.01)  (the table's axis; the bake clamps NdotV at 1e-4)
//     r = roughness
//     x = sqrt(2 (u^2 + r^2)) - 1                    distance from the mirror-grazing corner
//     y = 2 u^1.5 / (u^1.5 + r^1.5) - 1              direction about that corner
// where the table is discontinuous (near it bbar depends on NdotV / alpha). Why a quadrature:
// along roughness 0 the table is the basis itself (a polynomial of degree 20 in u for the powers
// basis), while the quadrature is mu_a = mu_b = NdotV and E = 1 there; smooth fields of low degree
// follow it where four channels of degree 11 each were needed.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"

namespace matc::runtime {

inline constexpr std::size_t kAnalyticLutAlbedoDegree = 12;
inline constexpr std::size_t kAnalyticLutQuadratureDegree = 6;
inline constexpr double kAnalyticLutMinU = 0.01;

// Coefficients of a polynomial of total degree d: T_p(x) T_q(y) for p + q <= d, ordered by p,
// then q.
constexpr std::size_t analytic_lut_terms(std::size_t degree) {
  return (degree + 1) * (degree + 2) / 2;
}
using AnalyticLutAlbedo = std::array<double, analytic_lut_terms(kAnalyticLutAlbedoDegree)>;
using AnalyticLutField = std::array<double, analytic_lut_terms(kAnalyticLutQuadratureDegree)>;

struct AnalyticLutCoefficients {
  BasisKind basis = kDefaultBasis;  // whose shader basis the nodes evaluate
  AnalyticLutAlbedo albedo{};       // E
  AnalyticLutField node_a{};        // mu_a
  AnalyticLutField node_b{};        // mu_b
  AnalyticLutField weight_b{};      // t
};

// The checked-in fit of each shipped basis (src/generated/<basis>_analytic_lut_table.cpp).
const AnalyticLutCoefficients& shipped_analytic_lut(BasisKind kind);

// (x, y) above at (NdotV, roughness), inputs clamped to [0, 1].
std::array<double, 2> analytic_lut_coordinates(double ndotv, double roughness);

// T_0..T_12 at x, by T_k = 2 x T_(k-1) - T_(k-2), as the shaders compute them.
using AnalyticLutChebyshev = std::array<double, kAnalyticLutAlbedoDegree + 1>;
AnalyticLutChebyshev analytic_lut_chebyshev(double x);

// sum_p T_p(x) (sum_q a_pq T_q(y)) over p + q <= degree, in the order the shaders sum it.
double analytic_lut_polynomial(std::span<const double> coefficients, std::size_t degree,
                               const AnalyticLutChebyshev& tx, const AnalyticLutChebyshev& ty);

// E, mu_a, mu_b and t at (NdotV, roughness).
struct AnalyticLutFields {
  double albedo = 0.0;
  double node_a = 0.0;
  double node_b = 0.0;
  double weight_b = 0.0;
};
AnalyticLutFields analytic_lut_fields(const AnalyticLutCoefficients& coefficients, double ndotv,
                                      double roughness);

// bbar_0..bbar_3 at (NdotV, roughness): what matc_preintegrated_basis_analytic returns.
std::array<double, kBasisSize> preintegrated_basis_analytic(
    const AnalyticLutCoefficients& coefficients, double ndotv, double roughness);

// Fbar = sum_i c_i bbar_i per channel, from the closed form instead of a fetch.
Rgb evaluate_fbar_analytic(const Coefficients& coefficients,
                           const AnalyticLutCoefficients& analytic, double ndotv, double roughness);

}  // namespace matc::runtime
