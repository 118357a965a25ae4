#include "basis/basis_polynomial_fit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "fit/minimax.h"

namespace matc {
namespace {

using Eigen::Index;
using runtime::kPolynomialDegree;
using runtime::kPolynomialSegments;

}  // namespace

runtime::BasisPolynomial fit_basis_polynomial(const runtime::BasisView& basis) {
  runtime::BasisPolynomial polynomial{};
  for (std::size_t segment = 0; segment < kPolynomialSegments; ++segment) {
    std::vector<std::size_t> samples;
    std::vector<double> ts;
    for (std::size_t j = 0; j < basis.samples(); ++j) {
      const runtime::PolynomialPosition position = runtime::polynomial_position(basis.mu_at(j));
      if (position.segment != segment) continue;
      samples.push_back(j);
      ts.push_back(position.t);
    }
    const auto rows = static_cast<Index>(samples.size());
    Eigen::MatrixXd design(rows, static_cast<Index>(kPolynomialDegree + 1));
    for (Index row = 0; row < rows; ++row) {
      // Columns t^degree .. t^0, the order Horner's rule consumes them in.
      double power = 1.0;
      for (Index column = kPolynomialDegree; column >= 0; --column) {
        design(row, column) = power;
        power *= ts[static_cast<std::size_t>(row)];
      }
    }
    for (std::size_t element = 0; element < 3; ++element) {
      Eigen::VectorXd values(rows);
      for (Index row = 0; row < rows; ++row)
        values(row) = basis.tables[element][samples[static_cast<std::size_t>(row)]];
      const Eigen::VectorXd fit = near_minimax_fit(design, values);
      for (std::size_t power = 0; power <= kPolynomialDegree; ++power) {
        polynomial[segment][power][element] =
            static_cast<double>(static_cast<float>(fit(static_cast<Index>(power))));
      }
    }
  }
  return polynomial;
}

PolynomialFitError polynomial_fit_error(const runtime::BasisPolynomial& polynomial,
                                        const runtime::BasisView& basis) {
  constexpr std::size_t kRefinement = 16;
  PolynomialFitError error;
  const std::size_t fine_samples = (basis.samples() - 1) * kRefinement + 1;
  for (std::size_t k = 0; k < fine_samples; ++k) {
    const double mu = static_cast<double>(k) / static_cast<double>(fine_samples - 1);
    const auto fitted = runtime::evaluate_basis_polynomial(polynomial, mu);
    const auto tabulated = basis.evaluate(mu);
    auto& worst = k % kRefinement == 0 ? error.at_grid_points : error.between_grid_points;
    for (std::size_t i = 0; i < 3; ++i)
      worst[i] = std::max(worst[i], std::abs(fitted[i + 1] - tabulated[i + 1]));
  }
  for (std::size_t i = 0; i < 3; ++i)
    error.between_grid_points[i] = std::max(error.between_grid_points[i], error.at_grid_points[i]);
  return error;
}

}  // namespace matc
