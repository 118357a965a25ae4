// Can a basis fit F82-tint materials (OpenPBR's metal) within 0.002, and at what cost to measured
// metals? Each candidate basis is fitted here from its training set (the shipped construction:
// first singular vector, curves weighted by 1 - F0, near-minimax solve) and scored on the 23
// reliable measured metals and on F82-tint curves. docs/accuracy.md, "F82-tint materials".
//   matc_f82_basis_study   (about a minute on 2 cores; bench/accuracy/update-docs.sh runs it)
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <Eigen/Dense>

#include "error_totals.h"
#include "matc/basis/basis_fit.h"
#include "matc/basis/basis_polynomial_fit.h"
#include "matc/fit/accuracy.h"
#include "matc/fit/coefficients.h"
#include "matc/optics/presets.h"
#include "matc/optics/reflectance_curve.h"
#include "matc/optics/spectral.h"

namespace {

using matc::FittedBasis;
using matc::TrainingCurve;

using matc::bench::Totals;

double max_error(const matc::ReflectanceCurve& curve, const FittedBasis& basis) {
  const auto coefficients = matc::solve_coefficients_minimax(curve, basis.polynomial);
  return matc::worst_channel(
      matc::measure_accuracy(curve, coefficients, basis.polynomial).decomposition.max_abs);
}

TrainingCurve f82_curve(double f0, double tint) {
  return [f0, tint](double mu) {
    return matc::fresnel_f82_tint(mu, f0, tint * matc::fresnel_schlick(matc::kF82MuBar, f0));
  };
}

// F82-tint training curves: F0 over (0, 0.95], tint over [tint_min, 1], strata midpoints.
std::vector<TrainingCurve> f82_training(double tint_min) {
  std::vector<TrainingCurve> curves;
  constexpr int kF0Steps = 40;
  constexpr int kTintSteps = 20;
  for (int i = 0; i < kF0Steps; ++i) {
    for (int j = 0; j < kTintSteps; ++j) {
      const double f0 = 0.95 * (i + 0.5) / kF0Steps;
      const double tint = tint_min + (1.0 - tint_min) * (j + 0.5) / kTintSteps;
      curves.push_back(f82_curve(f0, tint));
    }
  }
  return curves;
}

std::vector<TrainingCurve> extended_training() {
  std::vector<TrainingCurve> curves;
  for (const matc::ComplexIor ior : matc::extended_training_iors())
    curves.emplace_back([ior](double mu) { return matc::fresnel_exact(mu, ior); });
  return curves;
}

struct Candidate {
  std::string name;
  std::vector<TrainingCurve> training;
};

std::vector<double> as_vector(const Eigen::VectorXd& v) {
  return {v.data(), v.data() + v.size()};
}

// F82-tint's normalised curve is (1 - mu)^5 - a' mu (1 - mu)^6 exactly: a basis whose b_1, b_2
// span those two functions fits every F82-tint material (up to the shaders' polynomial form).
// b_3 is then the first singular vector of what they leave of the shipped training set (weighted
// by 1 - F0, like the shipped fit), free for conductors.
FittedBasis f82_spanning_basis() {
  constexpr Eigen::Index kSamples = 1000;
  Eigen::VectorXd b1(kSamples);
  Eigen::VectorXd b2(kSamples);
  for (Eigen::Index j = 0; j < kSamples; ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(kSamples - 1);
    b1(j) = std::pow(1.0 - mu, 5.0);
    b2(j) = mu * std::pow(1.0 - mu, 6.0);
  }
  b2 /= b2.maxCoeff();
  Eigen::MatrixXd span(kSamples, 2);
  span << b1, b2;
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(span).householderQ() *
                            Eigen::MatrixXd::Identity(kSamples, 2);
  const std::vector<matc::ComplexIor> iors = matc::extended_training_iors();
  Eigen::MatrixXd residual(static_cast<Eigen::Index>(iors.size()), kSamples);
  for (std::size_t row = 0; row < iors.size(); ++row) {
    const double f0 = matc::fresnel_exact(1.0, iors[row]);
    for (Eigen::Index j = 0; j < kSamples; ++j) {
      const double mu = static_cast<double>(j) / static_cast<double>(kSamples - 1);
      // Weighted by 1 - F0: (F - F0) / (1 - F0) x (1 - F0).
      residual(static_cast<Eigen::Index>(row), j) = matc::fresnel_exact(mu, iors[row]) - f0;
    }
    residual.row(static_cast<Eigen::Index>(row)) -=
        (1.0 - f0) * b1.transpose();  // c_1 = 1 - F0 is fixed: only b_2, b_3 are free
  }
  residual -= residual * q.col(1) * q.col(1).transpose();
  residual -= residual * q.col(0) * q.col(0).transpose();
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(residual, Eigen::ComputeThinV);
  Eigen::VectorXd b3 = svd.matrixV().col(0);
  Eigen::Index peak = 0;
  b3.cwiseAbs().maxCoeff(&peak);
  b3 /= b3(peak);
  FittedBasis basis;
  basis.tables = {as_vector(b1), as_vector(b2), as_vector(b3)};
  basis.kind = matc::runtime::BasisKind::extended;
  basis.probe_indices = {0, 0};  // unused by the minimax solve
  basis.polynomial = matc::fit_basis_polynomial(basis.view());
  return basis;
}

}  // namespace

int main() {
  std::vector<Candidate> candidates;
  candidates.push_back(
      {"**shipped `extended`** (dielectrics and conductors)", extended_training()});
  for (const double tint_min : {0.7, 0.5}) {
    Candidate both{fmt::format("`extended` + 800 F82-tint curves, tint in [{:.1f}, 1]", tint_min),
                   extended_training()};
    for (TrainingCurve& curve : f82_training(tint_min))
      both.training.push_back(std::move(curve));
    candidates.push_back(std::move(both));
  }

  // The scoring sets: measured metals (exact spectral curves), a grey F82-tint grid, and each
  // metal's own F82-tint parameters (F0 and F(1/7) of its exact curve).
  std::vector<matc::SpectralCurve> metals;
  std::vector<matc::F82TintCurve> metal_f82;
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    if (!preset.caveat.empty()) continue;
    metals.emplace_back(matc::preset_spectrum(preset));
    const matc::Rgb f0 = metals.back().at(1.0);
    const matc::Rgb f82 = metals.back().at(matc::kF82MuBar);
    matc::Rgb tint{};
    for (std::size_t c = 0; c < 3; ++c)
      tint[c] = std::min(1.0, f82[c] / matc::fresnel_schlick(matc::kF82MuBar, f0[c]));
    metal_f82.emplace_back(f0, tint);
  }

  fmt::print(
      "| basis trained on | metals worst | metals mean | F82-tint, tint 0.7-1 | F82-tint, tint "
      "0.5-1 "
      "| metals as F82-tint, worst / mean |\n|---|---:|---:|---:|---:|---:|\n");
  for (std::size_t i = 0; i <= candidates.size(); ++i) {
    FittedBasis basis;
    std::string name;
    if (i < candidates.size()) {
      basis = matc::fit_basis(candidates[i].training, matc::kExtendedConstruction);
      basis.kind = matc::runtime::BasisKind::extended;
      name = candidates[i].name;
    } else {
      basis = f82_spanning_basis();
      name = "b_1 = (1 - mu)^5, b_2 = mu (1 - mu)^6 (F82-tint's span), b_3 from `extended`'s rest";
    }
    Totals measured;
    for (const auto& curve : metals)
      measured.add_one(max_error(curve, basis));
    // Tints from 0.5: lower ones take low-F0 curves below 0, where every decomposition (and every
    // renderer) clamps, whatever the basis.
    double high_tints = 0.0;
    double mid_tints = 0.0;
    for (const double f0 : {0.02, 0.2, 0.4, 0.6, 0.8, 0.9, 0.95}) {
      for (const double tint : {0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 1.0}) {
        const double error = max_error(matc::F82TintCurve({f0, f0, f0}, {tint, tint, tint}), basis);
        mid_tints = std::max(mid_tints, error);
        if (tint >= 0.7) high_tints = std::max(high_tints, error);
      }
    }
    Totals as_f82;
    for (const auto& curve : metal_f82)
      as_f82.add_one(max_error(curve, basis));
    fmt::print("| {} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} / {:.4f} |\n", name,
               measured.worst, measured.mean(), high_tints, mid_tints, as_f82.worst, as_f82.mean());
  }
  return 0;
}
