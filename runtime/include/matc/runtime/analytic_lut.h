// The preintegrated table in closed form, for shaders that cannot bind a texture (issue #20,
// docs/lut.md "A closed form"). Each channel bbar_i(NdotV, roughness) of the table is one
// polynomial of degree 11 in each of two coordinates, fitted by `matc basis analytic-lut` from
// the baked 128x128 table of each shipped basis:
//     u = max(sqrt(NdotV), 0.01)  (the table's axis; the bake clamps NdotV at 1e-4)
//     r = roughness
//     x = sqrt(2 (u^2 + r^2)) - 1                    distance from the mirror-grazing corner
//     y = 2 u^1.5 / (u^1.5 + r^1.5) - 1              direction about that corner
// Polar coordinates about (u, r) = (0, 0), where the table is discontinuous: near it bbar
// depends on NdotV / alpha (a narrow valley along u = r) that no polynomial in (u, r) follows.
// bbar_i = sum_{p,q} a_ipq T_p(x) T_q(y) in Chebyshev polynomials (monomial coefficients would
// reach ~2e3 and cancel to 2e-4 in float32), evaluated by shaders as 3x3 blocks of mat4 products
// with T_4..T_11 from T_0..T_3 by T_(m+n) = 2 T_m T_n - T_|m-n|.
#pragma once

#include <array>
#include <cstddef>

#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"

namespace matc::runtime {

inline constexpr std::size_t kAnalyticLutTerms = 12;  // powers 0..11 of x and of y
inline constexpr double kAnalyticLutMinU = 0.01;

// Coefficients a[channel][p][q] of T_p(x) T_q(y).
using AnalyticLutCoefficients =
    std::array<std::array<std::array<double, kAnalyticLutTerms>, kAnalyticLutTerms>, kBasisSize>;

// The checked-in fit of each shipped basis (src/<basis>_analytic_lut_table.cpp).
const AnalyticLutCoefficients& shipped_analytic_lut(BasisKind kind);

// (x, y) above at (NdotV, roughness), inputs clamped to [0, 1].
std::array<double, 2> analytic_lut_coordinates(double ndotv, double roughness);

// T_0..T_11 at x, as the shaders compute them.
std::array<double, kAnalyticLutTerms> analytic_lut_chebyshev(double x);

// bbar_0..bbar_3 at (NdotV, roughness): what matc_preintegrated_basis_analytic returns.
std::array<double, kBasisSize> preintegrated_basis_analytic(
    const AnalyticLutCoefficients& coefficients, double ndotv, double roughness);

// Fbar = sum_i c_i bbar_i per channel, from the closed form instead of a fetch.
Rgb evaluate_fbar_analytic(const Coefficients& coefficients,
                           const AnalyticLutCoefficients& analytic, double ndotv, double roughness);

}  // namespace matc::runtime
