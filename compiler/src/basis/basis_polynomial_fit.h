// Fitting the shaders' piecewise-polynomial form of a tabulated basis (runtime/basis_polynomial.h).
#pragma once

#include <array>

#include "matc/runtime/basis.h"
#include "matc/runtime/basis_polynomial.h"

namespace matc {

// Near-minimax fit (Lawson's iteratively reweighted least squares) of b_1..b_3 at the table's
// grid points, segment by segment, with coefficients rounded to float.
runtime::BasisPolynomial fit_basis_polynomial(const runtime::BasisView& basis);

struct PolynomialFitError {
  std::array<double, 3> at_grid_points{};  // max |polynomial - table| over the table's samples
  // ... and over a 16x finer grid, where the table's own linear interpolation adds its error.
  std::array<double, 3> between_grid_points{};
};
PolynomialFitError polynomial_fit_error(const runtime::BasisPolynomial& polynomial,
                                        const runtime::BasisView& basis);

}  // namespace matc
