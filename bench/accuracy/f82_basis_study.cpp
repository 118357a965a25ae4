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

#include "basis/basis_fit.h"
#include "error_totals.h"
#include "f82_tint_look.h"
#include "fit/accuracy.h"
#include "fit/coefficients.h"
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
  for (std::size_t i = 0; i <= candidates.size(); ++i) {
    FittedBasis basis;
    std::string name;
    if (i < candidates.size()) {
      basis = matc::fit_basis(candidates[i].training, matc::kExtendedConstruction);
      basis.kind = matc::runtime::BasisKind::extended;
      name = candidates[i].name;
    } else {
      basis = matc::fit_f82_basis();
      name =
          "**shipped `f82`**: b_1 = (1 - mu)^5, b_2 = mu (1 - mu)^6 (F82-tint's span), b_3 from "
          "`extended`'s rest";
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
