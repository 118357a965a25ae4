#include "matc/fit/conductor_solver.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "matc/fit/coefficients.h"
#include "matc/optics/gulbrandsen.h"
#include "matc/optics/reflectance_curve.h"
#include "matc/runtime/basis_polynomial.h"

namespace matc {
namespace {

constexpr int kLawsonIterations = 40;  // as solve_coefficients_minimax

using Array = Eigen::ArrayXd;

Eigen::Map<const Array> as_array(const std::vector<double>& values) {
  return {values.data(), static_cast<Eigen::Index>(values.size())};
}

}  // namespace

ConductorSolver::ConductorSolver(runtime::BasisKind basis) : basis_(basis) {
  const runtime::BasisPolynomial& polynomial = runtime::shipped_basis_polynomial(basis);
  for (std::size_t j = 0; j < kMinimaxCosines; ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(kMinimaxCosines - 1);
    const auto b = runtime::evaluate_basis_polynomial(polynomial, mu);
    mu_.push_back(mu);
    b1_.push_back(b[1]);
    b2_.push_back(b[2]);
    b3_.push_back(b[3]);
  }
}

ChannelSolution ConductorSolver::solve(double reflectivity, double edge_tint) const {
  const double r = std::isnan(reflectivity) ? 0.0 : std::clamp(reflectivity, 0.0, 1.0);
  const double g = std::isnan(edge_tint) ? 0.0 : std::clamp(edge_tint, 0.0, 1.0);
  if (r >= 1.0) return {{1.0, 0.0, 0.0, 0.0}, 0.0};  // F = 1 at every angle
  const ComplexIor ior = gulbrandsen_to_ior({r, g});
  const auto rows = static_cast<Eigen::Index>(mu_.size());
  const auto b1 = as_array(b1_), b2 = as_array(b2_), b3 = as_array(b3_);
  Array exact(rows);
  for (Eigen::Index j = 0; j < rows; ++j)
    exact(j) = fresnel_conductor(mu_[static_cast<std::size_t>(j)], ior);
  const double c0 = fresnel_conductor(1.0, ior);
  const Array residual = exact - c0 - (1.0 - c0) * b1;

  double c2 = 0.0, c3 = 0.0;
  if (basis_ == runtime::BasisKind::paper) {
    const runtime::Coefficients probes =
        solve_coefficients_at_probes(IorCurve({ior, ior, ior}), runtime::shipped_basis(basis_));
    c2 = probes[0][2];
    c3 = probes[0][3];
  } else {
    // Lawson's iterations exactly as near_minimax_fit runs them (weighted least squares, weights
    // times the square-rooted error, rescaled to a largest weight of 1), with the 2x2 normal
    // equations in place of a QR of the 401 x 2 design: same iterates up to rounding.
    // Lawson's iterations as near_minimax_fit runs them (weighted least squares; weights times
    // the square-rooted error, rescaled to a largest weight of 1), with the 2x2 normal equations
    // in place of a QR of the 401 x 2 design, in single precision (twice the SIMD width): F
    // within 1e-5 of solve_coefficients', ten times faster (the solve runs once per distinct
    // texel pair, tens of thousands of times a texture).
    const Eigen::ArrayXf f2 = b2.cast<float>(), f3 = b3.cast<float>();
    const Eigen::ArrayXf y = residual.cast<float>();
    Eigen::ArrayXf weights = Eigen::ArrayXf::Ones(rows);
    for (int iteration = 0; iteration <= kLawsonIterations; ++iteration) {
      const Eigen::ArrayXf w2 = weights.square();
      const Eigen::ArrayXf w2b2 = w2 * f2, w2b3 = w2 * f3;
      const double a00 = (w2b2 * f2).sum(), a01 = (w2b2 * f3).sum(), a11 = (w2b3 * f3).sum();
      const double y0 = (w2b2 * y).sum(), y1 = (w2b3 * y).sum();
      const double determinant = a00 * a11 - a01 * a01;
      c2 = (y0 * a11 - a01 * y1) / determinant;
      c3 = (a00 * y1 - a01 * y0) / determinant;
      weights *=
          ((static_cast<float>(c2) * f2 + static_cast<float>(c3) * f3 - y).abs() + 1e-15f).sqrt();
      weights /= weights.maxCoeff();
    }
  }
  const double max_error = (c2 * b2 + c3 * b3 - residual).abs().maxCoeff();
  return {{r, 1.0 - r, c2, c3}, max_error};
}

}  // namespace matc
