#include "fit/coefficients.h"

#include <cmath>
#include <stdexcept>

#include "fit/minimax.h"

namespace matc {

runtime::Coefficients solve_coefficients_at_probes(const ReflectanceCurve& curve,
                                                   const runtime::BasisView& basis) {
  const Rgb f0 = curve.at(1.0);
  const Rgb f90 = curve.grazing_value().value_or(Rgb{1.0, 1.0, 1.0});
  const auto probe1 = basis.at_index(basis.probe_indices[0]);
  const auto probe2 = basis.at_index(basis.probe_indices[1]);
  const Rgb f_probe1 = curve.at(basis.probe_mu(0));
  const Rgb f_probe2 = curve.at(basis.probe_mu(1));

  // [b2(p1) b3(p1); b2(p2) b3(p2)] [c2 c3]^T = residual at the probes (Cramer's rule).
  const double determinant = probe1[2] * probe2[3] - probe1[3] * probe2[2];
  if (determinant == 0.0) throw std::logic_error("basis probes do not separate b_2 and b_3");

  runtime::Coefficients coefficients{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double c0 = f0[c];
    const double c1 = f90[c] - c0;
    const double y1 = f_probe1[c] - c0 - c1 * probe1[1];
    const double y2 = f_probe2[c] - c0 - c1 * probe2[1];
    const double c2 = (y1 * probe2[3] - probe1[3] * y2) / determinant;
    const double c3 = (probe1[2] * y2 - y1 * probe2[2]) / determinant;
    coefficients[c] = {c0, c1, c2, c3};
  }
  return coefficients;
}

namespace {

// Fitted coefficients smaller than this are rounding noise (see solve_by_fit).
constexpr double kNegligibleCoefficient = 1e-12;

// (c_2, c_3) fitted to the residual after c_0 + c_1 b_1, by Lawson's iterations (0: least squares).
// A curve with its own grazing value (a metal seen through a coat) has c_1 fitted too: such a
// curve is flat near grazing, where b_1 is steep, so pinning F(0) costs more than it keeps.
runtime::Coefficients solve_by_fit(const ReflectanceCurve& curve,
                                   const runtime::ShaderBasis& shader_basis, int iterations) {
  constexpr auto kRows = static_cast<Eigen::Index>(kMinimaxCosines);
  const Rgb f0 = curve.at(1.0);
  const bool fit_c1 = curve.grazing_value().has_value();
  const Eigen::Index unknowns = fit_c1 ? 3 : 2;
  Eigen::MatrixXd design(kRows, unknowns);
  Eigen::MatrixXd residual(kRows, 3);
  for (Eigen::Index j = 0; j < kRows; ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(kRows - 1);
    const auto b = runtime::evaluate_shader_basis(shader_basis, mu);
    const Rgb exact = curve.at(mu);
    for (Eigen::Index i = 0; i < unknowns; ++i)
      design(j, i) = b[static_cast<std::size_t>(i + 4 - unknowns)];
    for (Eigen::Index c = 0; c < 3; ++c) {
      const double c0 = f0[static_cast<std::size_t>(c)];
      const double pinned = fit_c1 ? 0.0 : (1.0 - c0) * b[1];
      residual(j, c) = exact[static_cast<std::size_t>(c)] - c0 - pinned;
    }
  }
  runtime::Coefficients coefficients{};
  for (std::size_t c = 0; c < 3; ++c) {
    Eigen::VectorXd fit =
        near_minimax_fit(design, residual.col(static_cast<Eigen::Index>(c)), iterations);
    // A coefficient the curve does not need (c_3 of an F82-tint curve in the f82 basis, whose
    // span holds it) comes out as rounding noise near 1e-16, which differs between builds of the
    // same code (native, WebAssembly) and would print: it is 0, far below what a float32 shader
    // resolves.
    for (Eigen::Index i = 0; i < fit.size(); ++i) {
      if (std::abs(fit(i)) < kNegligibleCoefficient) fit(i) = 0.0;
    }
    if (fit_c1) {
      coefficients[c] = {f0[c], fit(0), fit(1), fit(2)};
    } else {
      coefficients[c] = {f0[c], 1.0 - f0[c], fit(0), fit(1)};
    }
  }
  return coefficients;
}

}  // namespace

runtime::Coefficients solve_coefficients_minimax(const ReflectanceCurve& curve,
                                                 const runtime::ShaderBasis& shader_basis) {
  return solve_by_fit(curve, shader_basis, 40);
}

runtime::Coefficients solve_coefficients_least_squares(const ReflectanceCurve& curve,
                                                       const runtime::ShaderBasis& shader_basis) {
  return solve_by_fit(curve, shader_basis, 0);
}

runtime::Coefficients solve_coefficients(const ReflectanceCurve& curve,
                                         const runtime::BasisView& basis) {
  if (basis.kind == runtime::BasisKind::paper) return solve_coefficients_at_probes(curve, basis);
  return solve_coefficients_minimax(curve, runtime::shipped_shader_basis(basis.kind));
}

}  // namespace matc
