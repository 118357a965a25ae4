// The coefficient solve and the accuracy it reaches on the measured metals.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "compile/compile.h"
#include "fit/accuracy.h"
#include "fit/coefficients.h"
#include "optics/gulbrandsen.h"
#include "optics/presets.h"
#include "optics/reflectance_curve.h"
#include "optics/spectral.h"

namespace matc {
namespace {

const runtime::BasisView kBasis = runtime::paper_basis();

void expect_constraints_hold(const ReflectanceCurve& curve, const std::string& what) {
  const runtime::Coefficients c = solve_coefficients(curve, kBasis);
  const auto f = [&](double mu) { return runtime::evaluate_fresnel(c, kBasis, mu); };
  for (std::size_t ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(c[ch][0] + c[ch][1], 1.0, 1e-15) << what;
    EXPECT_NEAR(f(1.0)[ch], curve.at(1.0)[ch], 1e-9) << what << ": F(0 deg)";
    EXPECT_NEAR(f(0.0)[ch], 1.0, 1e-9) << what << ": F(90 deg)";
    for (std::size_t p = 0; p < 2; ++p) {
      const double mu = kBasis.probe_mu(p);
      EXPECT_NEAR(f(mu)[ch], curve.at(mu)[ch], 1e-12) << what << ": probe " << p;
    }
  }
}

TEST(Coefficients, MatchTheExactCurveAtBothEndsAndBothProbes) {
  for (const MetalPreset& preset : metal_presets()) {
    expect_constraints_hold(SpectralCurve(preset_spectrum(preset)), std::string(preset.symbol));
  }
  expect_constraints_hold(IorCurve({{{1.5, 0.0}, {0.2, 3.0}, {2.5, 1.0}}}), "ior");
}

TEST(Coefficients, ArtisticAndEquivalentIorGiveTheSameCoefficients) {
  Material artistic;
  artistic.name = "a";
  artistic.model = ArtisticInput{{0.9, 0.6, 0.3}, {0.2, 0.5, 0.9}};
  const CompiledMaterial from_artistic = compile_material(artistic, kBasis);
  const auto& ior = *from_artistic.ior;
  Material as_ior;
  as_ior.name = "b";
  as_ior.model = IorInput{{ior[0].n, ior[1].n, ior[2].n}, {ior[0].k, ior[1].k, ior[2].k}};
  const CompiledMaterial from_ior = compile_material(as_ior, kBasis);
  for (std::size_t ch = 0; ch < 3; ++ch) {
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_DOUBLE_EQ(from_artistic.coefficients[ch][i], from_ior.coefficients[ch][i]);
    }
  }
}

TEST(Coefficients, DecompositionIsClampedAtZero) {
  // A weak dielectric dips below zero between probes; the evaluation clamps as the shader does.
  const runtime::Coefficients c = {
      {{0.0, 1.0, -5.0, 0.0}, {0.0, 1.0, -5.0, 0.0}, {0.0, 1.0, -5.0, 0.0}}};
  for (const double value : runtime::evaluate_fresnel(c, kBasis, kBasis.probe_mu(0))) {
    EXPECT_EQ(value, 0.0);
  }
}

struct Summary {
  double worst = 0.0;
  double mean_of_max = 0.0;
};

// Over the 23 measured metals (Zn excluded as unreliable), every channel counted as one curve.
Summary summarise(ErrorStats FitAccuracy::*model,
                  runtime::BasisKind kind = runtime::BasisKind::paper) {
  const runtime::BasisView basis = runtime::shipped_basis(kind);
  Summary summary;
  std::size_t curves = 0;
  for (const MetalPreset& preset : metal_presets()) {
    if (!preset.caveat.empty()) continue;
    const SpectralCurve curve(preset_spectrum(preset));
    const FitAccuracy accuracy = measure_accuracy(curve, solve_coefficients(curve, basis),
                                                  runtime::shipped_shader_basis(kind), 501);
    for (const double max_error : (accuracy.*model).max_abs) {
      summary.worst = std::max(summary.worst, max_error);
      summary.mean_of_max += max_error;
      ++curves;
    }
  }
  EXPECT_EQ(curves, 69u);
  summary.mean_of_max /= static_cast<double>(curves);
  return summary;
}

// Reference figures for the authors' construction on the 23 measured metals (issue #2):
// worst-channel max 0.019 and mean per-curve max 0.009; Schlick 0.23 / 0.12; F82-tint 0.040 /
// 0.015.
TEST(Accuracy, ReproducesThePublishedFiguresOnMeasuredMetals) {
  const Summary ours = summarise(&FitAccuracy::decomposition);
  EXPECT_NEAR(ours.worst, 0.019, 0.001);
  EXPECT_NEAR(ours.mean_of_max, 0.009, 0.0005);
  const Summary schlick = summarise(&FitAccuracy::schlick);
  EXPECT_NEAR(schlick.worst, 0.23, 0.005);
  EXPECT_NEAR(schlick.mean_of_max, 0.12, 0.005);
  const Summary f82 = summarise(&FitAccuracy::f82_tint);
  EXPECT_NEAR(f82.worst, 0.040, 0.001);
  EXPECT_NEAR(f82.mean_of_max, 0.015, 0.0006);
}

// Issue #8's targets for the default basis, which never saw a measured metal (its training set
// is the authors'): worst-channel max <= 0.010, mean per-curve max <= 0.004.
TEST(Accuracy, DefaultBasisMeetsTheTargetsOnMeasuredMetals) {
  const Summary ours = summarise(&FitAccuracy::decomposition, runtime::BasisKind::extended);
  EXPECT_LE(ours.worst, 0.010);
  EXPECT_LE(ours.mean_of_max, 0.004);
}

// ... while staying no worse than the authors' basis on artistic inputs with r <= 0.8, in the
// worst case and on average over an (r, g) grid.
TEST(Accuracy, DefaultBasisIsNoWorseThanThePaperOnArtisticInputs) {
  std::array<double, 2> worst{};
  std::array<double, 2> sum{};
  for (int i = 1; i <= 16; ++i) {
    for (int j = 0; j <= 10; ++j) {
      const ComplexIor ior = gulbrandsen_to_ior({0.05 * i, 0.1 * j});
      const IorCurve curve({ior, ior, ior});
      std::size_t b = 0;
      for (const auto kind : {runtime::BasisKind::extended, runtime::BasisKind::paper}) {
        const double error =
            measure_accuracy(curve, solve_coefficients(curve, runtime::shipped_basis(kind)),
                             runtime::shipped_shader_basis(kind), 501)
                .decomposition.max_abs[0];
        worst[b] = std::max(worst[b], error);
        sum[b++] += error;
      }
    }
  }
  EXPECT_LE(worst[0], worst[1]);
  EXPECT_LE(sum[0], sum[1]);
}

TEST(Coefficients, MinimaxSolveKeepsBothEndsExact) {
  const runtime::BasisView basis = runtime::shipped_basis(runtime::BasisKind::extended);
  const auto& shader_basis = runtime::shipped_shader_basis(runtime::BasisKind::extended);
  for (const MetalPreset& preset : metal_presets()) {
    const SpectralCurve curve(preset_spectrum(preset));
    const runtime::Coefficients c = solve_coefficients(curve, basis);
    for (std::size_t ch = 0; ch < 3; ++ch) {
      EXPECT_NEAR(c[ch][0], curve.at(1.0)[ch], 1e-15) << preset.symbol;
      EXPECT_NEAR(c[ch][0] + c[ch][1], 1.0, 1e-15) << preset.symbol;
      // Through the shaders' polynomials, which hold the basis' end values to 1e-4.
      EXPECT_NEAR(runtime::evaluate_fresnel(c, shader_basis, 1.0)[ch], curve.at(1.0)[ch], 1e-4);
      EXPECT_NEAR(runtime::evaluate_fresnel(c, shader_basis, 0.0)[ch], 1.0, 1e-4);
    }
  }
}

TEST(Coefficients, MinimaxSolveBeatsProbesOnTheSameBasis) {
  const runtime::BasisView basis = runtime::shipped_basis(runtime::BasisKind::extended);
  const auto& shader_basis = runtime::shipped_shader_basis(runtime::BasisKind::extended);
  const SpectralCurve curve(preset_spectrum(*find_metal_preset("Hg")));
  const double minimax =
      measure_accuracy(curve, solve_coefficients_minimax(curve, shader_basis), shader_basis)
          .decomposition.max_abs[1];
  const double probes =
      measure_accuracy(curve, solve_coefficients_at_probes(curve, basis), shader_basis)
          .decomposition.max_abs[1];
  EXPECT_LT(minimax, probes);
}

// Issue #17's target for OpenPBR metals: max |F - F82-tint curve| <= 0.002 over the artistic
// range. The f82 basis spans every F82-tint curve in the closed form the shaders evaluate, so
// only rounding is left; the default basis, fitted to exact curves, misses the target
// (docs/accuracy.md).
TEST(Accuracy, F82BasisFitsF82TintMaterialsWithinTheTarget) {
  std::array<double, 2> worst{};  // f82, extended
  for (int i = 0; i <= 19; ++i) {
    for (int j = 0; j <= 10; ++j) {
      const F82TintCurve curve({0.05 * i, 0.05 * i, 0.05 * i}, {0.1 * j, 0.1 * j, 0.1 * j});
      std::size_t b = 0;
      for (const auto kind : {runtime::BasisKind::f82, runtime::BasisKind::extended}) {
        const auto& shader_basis = runtime::shipped_shader_basis(kind);
        const double error =
            measure_accuracy(curve, solve_coefficients(curve, runtime::shipped_basis(kind)),
                             shader_basis, 501)
                .decomposition.max_abs[0];
        worst[b] = std::max(worst[b], error);
        ++b;
      }
    }
  }
  EXPECT_LE(worst[0], 1e-12);
  EXPECT_GT(worst[1], 0.002);
}

// A tint of 1 is Schlick's curve: b_1 alone, so c_2 and c_3 vanish (to rounding).
TEST(Coefficients, F82BasisHoldsSchlickInItsFirstTwoTerms) {
  const runtime::BasisView basis = runtime::shipped_basis(runtime::BasisKind::f82);
  for (const double f0 : {0.02, 0.5, 0.9}) {
    const auto c = solve_coefficients(F82TintCurve({f0, f0, f0}, {1.0, 1.0, 1.0}), basis)[0];
    EXPECT_DOUBLE_EQ(c[0], f0);
    EXPECT_NEAR(c[2], 0.0, 1e-12) << f0;
    EXPECT_NEAR(c[3], 0.0, 1e-12) << f0;
  }
}

// What the f82 basis costs on exact conductor curves (measured 0.0134 / 0.0078): worse than the
// default (0.006 / 0.003), better than the authors' basis (0.019 / 0.009), far ahead of Schlick
// (0.23) and of F82-tint fitted to the same metals (0.040).
TEST(Accuracy, F82BasisStaysWellAheadOfSchlickOnMeasuredMetals) {
  const Summary f82 = summarise(&FitAccuracy::decomposition, runtime::BasisKind::f82);
  EXPECT_LE(f82.worst, 0.014);
  EXPECT_LE(f82.mean_of_max, 0.008);
}

TEST(Accuracy, RmsNeverExceedsMax) {
  const SpectralCurve curve(preset_spectrum(*find_metal_preset("Cr")));
  const FitAccuracy accuracy =
      measure_accuracy(curve, solve_coefficients(curve, kBasis),
                       runtime::shipped_shader_basis(matc::runtime::BasisKind::paper));
  for (const ErrorStats* stats : {&accuracy.decomposition, &accuracy.schlick, &accuracy.f82_tint}) {
    for (std::size_t ch = 0; ch < 3; ++ch) {
      EXPECT_GT(stats->rms[ch], 0.0);
      EXPECT_LE(stats->rms[ch], stats->max_abs[ch]);
    }
  }
  // Chromium is a case Schlick gets badly wrong and the decomposition does not.
  EXPECT_GT(accuracy.schlick.max_abs[1], 0.15);
  EXPECT_LT(accuracy.decomposition.max_abs[1], 0.015);
}

}  // namespace
}  // namespace matc
