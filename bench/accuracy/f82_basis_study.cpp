// Can a basis fit F82-tint materials (OpenPBR's metal) within 0.002, and at what cost to measured
// metals? Each candidate basis is fitted here from its training set (the shipped construction:
// first singular vector, curves weighted by 1 - F0, near-minimax solve) and scored on the 23
// reliable measured metals and on F82-tint curves, beside the shipped f82 basis.
// docs/accuracy.md, "F82-tint materials".
//   matc_f82_basis_study   (about a minute on 2 cores; bench/accuracy/update-docs.sh runs it)
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <Eigen/Dense>
#include <Eigen/SVD>

#include "basis/basis_fit.h"
#include "basis/basis_polynomial_fit.h"
#include "error_totals.h"
#include "f82_tint_look.h"
#include "fit/accuracy.h"
#include "fit/coefficients.h"
#include "optics/fresnel.h"
#include "optics/presets.h"
#include "optics/reflectance_curve.h"
#include "optics/spectral.h"

namespace {

using matc::FittedBasis;
using matc::TrainingCurve;

using matc::bench::Totals;

double max_error(const matc::ReflectanceCurve& curve, const FittedBasis& basis) {
  const auto coefficients = matc::solve_coefficients_minimax(curve, basis.shader);
  return matc::worst_channel(
      matc::measure_accuracy(curve, coefficients, basis.shader).decomposition.max_abs);
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

// The f82 basis before it was a closed form: b_1 = (1 - mu)^5, b_2 = mu (1 - mu)^6 scaled to a
// peak of 1, and b_3 the first singular vector of what they leave of the extended training set,
// every curve weighted by 1 - F0 (c_1 = 1 - F0 is fixed, so F - F0 - (1 - F0) b_1 is what b_2
// and b_3 hold; b_2's share is projected out). Its shader form is a piecewise polynomial.
FittedBasis fitted_b3_f82_basis() {
  using Eigen::Index;
  const auto samples = static_cast<Index>(matc::kExtendedConstruction.samples);
  Eigen::VectorXd schlick(samples);
  Eigen::VectorXd lobe(samples);
  for (Index j = 0; j < samples; ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(samples - 1);
    schlick(j) = std::pow(1.0 - mu, 5.0);
    lobe(j) = mu * std::pow(1.0 - mu, 6.0);
  }
  lobe /= lobe.maxCoeff();
  const std::vector<matc::ComplexIor> iors = matc::extended_training_iors();
  Eigen::MatrixXd residual(static_cast<Index>(iors.size()), samples);
  for (std::size_t row = 0; row < iors.size(); ++row) {
    const double f0 = matc::fresnel_exact(1.0, iors[row]);
    for (Index j = 0; j < samples; ++j) {
      const double mu = static_cast<double>(j) / static_cast<double>(samples - 1);
      residual(static_cast<Index>(row), j) =
          matc::fresnel_exact(mu, iors[row]) - f0 - (1.0 - f0) * schlick(j);
    }
  }
  const Eigen::VectorXd lobe_direction = lobe.normalized();
  residual -= (residual * lobe_direction) * lobe_direction.transpose();
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(residual, Eigen::ComputeThinV);
  Index peak = 0;
  svd.matrixV().col(0).cwiseAbs().maxCoeff(&peak);
  const Eigen::VectorXd third = svd.matrixV().col(0) / svd.matrixV()(peak, 0);

  FittedBasis basis;
  basis.tables = {std::vector<double>(schlick.data(), schlick.data() + samples),
                  std::vector<double>(lobe.data(), lobe.data() + samples),
                  std::vector<double>(third.data(), third.data() + samples)};
  basis.kind = matc::runtime::BasisKind::f82;
  // Probes matter only to the collocation solve; this study solves near-minimax.
  basis.probe_indices = matc::closed_form_fitted_basis(matc::runtime::BasisKind::f82).probe_indices;
  basis.shader = matc::fit_basis_polynomial(basis.view());
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
    const matc::bench::F82TintLook look = matc::bench::f82_tint_look(metals.back());
    metal_f82.emplace_back(look.f0, look.tint);
  }

  fmt::print(
      "| basis trained on | metals worst | metals mean | F82-tint, tint 0.7-1 | F82-tint, tint "
      "0.5-1 "
      "| metals as F82-tint, worst / mean |\n|---|---:|---:|---:|---:|---:|\n");
  for (std::size_t i = 0; i < candidates.size() + 2; ++i) {
    FittedBasis basis;
    std::string name;
    if (i < candidates.size()) {
      basis = matc::fit_basis(candidates[i].training, matc::kExtendedConstruction);
      basis.kind = matc::runtime::BasisKind::extended;
      name = candidates[i].name;
    } else if (i == candidates.size()) {
      basis = fitted_b3_f82_basis();
      name =
          "b_1 = (1 - mu)^5, b_2 = mu (1 - mu)^6 (F82-tint's span), b_3 fitted to `extended`'s "
          "rest (`f82` before it was a closed form)";
    } else {
      basis = matc::closed_form_fitted_basis(matc::runtime::BasisKind::f82);
      name = "**shipped `f82`**: (1 - mu)^5, mu (1 - mu)^6, mu (1 - mu)^11 in closed form";
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
