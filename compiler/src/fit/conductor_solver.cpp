#include "fit/conductor_solver.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "fit/coefficients.h"
#include "matc/runtime/shader_basis.h"
#include "optics/gulbrandsen.h"
#include "optics/reflectance_curve.h"

namespace matc {
namespace {

constexpr int kLawsonIterations = 40;  // as solve_coefficients_minimax

using Array = Eigen::ArrayXd;

Eigen::Map<const Array> as_array(const std::vector<double>& values) {
  return {values.data(), static_cast<Eigen::Index>(values.size())};
}

// Lawson's iterations as near_minimax_fit runs them (weighted least squares; weights times the
// square-rooted error, rescaled to a largest weight of 1), with the 2x2 normal equations in place
// of a QR of the 401 x 2 design, in single precision: F within 1e-5 of solve_coefficients'
// (tests/unit/bake/bake_test.cpp), twenty times faster. The solve runs once per distinct texel
// pair, up to 65,536 times a texture: the loops are SIMD reductions, compiled for AVX2 as well as
// the baseline and picked at load time.
__attribute__((target_clones("avx2", "default"))) std::pair<double, double> lawson_iterations(
    const float* b2, const float* b3, const float* y, float* weights, int rows) {
  for (int j = 0; j < rows; ++j)
    weights[j] = 1.0f;
  double c2 = 0.0, c3 = 0.0;
  for (int iteration = 0; iteration <= kLawsonIterations; ++iteration) {
    float a00 = 0.0f, a01 = 0.0f, a11 = 0.0f, y0 = 0.0f, y1 = 0.0f;
#pragma omp simd reduction(+ : a00, a01, a11, y0, y1)
    for (int j = 0; j < rows; ++j) {
      const float w2 = weights[j] * weights[j];
      const float w2b2 = w2 * b2[j], w2b3 = w2 * b3[j];
      a00 += w2b2 * b2[j];
      a01 += w2b2 * b3[j];
      a11 += w2b3 * b3[j];
      y0 += w2b2 * y[j];
      y1 += w2b3 * y[j];
    }
    const double determinant = double{a00} * a11 - double{a01} * a01;
    c2 = (double{y0} * a11 - double{a01} * y1) / determinant;
    c3 = (double{a00} * y1 - double{a01} * y0) / determinant;
    const auto fc2 = static_cast<float>(c2), fc3 = static_cast<float>(c3);
#pragma omp simd
    for (int j = 0; j < rows; ++j)
      weights[j] *= std::sqrt(std::fabs(fc2 * b2[j] + fc3 * b3[j] - y[j]) + 1e-15f);
    float largest = 0.0f;
#pragma omp simd reduction(max : largest)
    for (int j = 0; j < rows; ++j)
      largest = largest > weights[j] ? largest : weights[j];
#pragma omp simd
    for (int j = 0; j < rows; ++j)
      weights[j] /= largest;
  }
  return {c2, c3};
}

}  // namespace

ConductorSolver::ConductorSolver(runtime::BasisKind basis) : basis_(basis) {
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(basis);
  for (std::size_t j = 0; j < kMinimaxCosines; ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(kMinimaxCosines - 1);
    const auto b = runtime::evaluate_shader_basis(shader_basis, mu);
    mu_.push_back(mu);
    b1_.push_back(b[1]);
    b2_.push_back(b[2]);
    b3_.push_back(b[3]);
    b2_float_.push_back(static_cast<float>(b[2]));
    b3_float_.push_back(static_cast<float>(b[3]));
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
    std::vector<float> y(residual.begin(), residual.end());
    std::vector<float> weights(y.size());
    const auto [fit2, fit3] = lawson_iterations(b2_float_.data(), b3_float_.data(), y.data(),
                                                weights.data(), static_cast<int>(y.size()));
    c2 = fit2;
    c3 = fit3;
  }
  const double max_error = (c2 * b2 + c3 * b3 - residual).abs().maxCoeff();
  return {{r, 1.0 - r, c2, c3}, max_error};
}

}  // namespace matc
