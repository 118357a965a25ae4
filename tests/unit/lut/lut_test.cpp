// The preintegrated table: furnace tests, range, determinism, convergence, Karis' split sum, the
// sampling convention, energy companions and accuracy against a direct reference.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "fit/accuracy.h"
#include "fit/coefficients.h"
#include "lut/default_lut_hashes.h"
#include "lut/energy.h"
#include "lut/preintegrate.h"
#include "lut/split_sum_reference.h"
#include "optics/presets.h"
#include "optics/spectral.h"

namespace matc {
namespace {

const runtime::BasisView kBasis = runtime::paper_basis();

// One small table shared by the tests that only read it.
const Lut& small_lut() {
  static const Lut lut = preintegrate_lut(kBasis, {32, 256, 0});
  return lut;
}

TEST(Preintegration, SmoothSurfacesReturnTheBasisItself) {
  for (const double mu : {0.05, 0.3, 0.7, 1.0}) {
    const auto bbar = preintegrate_basis(kBasis, mu, 0.0, 256);
    const auto b = kBasis.evaluate(mu);
    EXPECT_NEAR(bbar[0], 1.0, 1e-6) << "furnace: a mirror reflects everything";
    for (std::size_t i = 1; i < 4; ++i)
      EXPECT_NEAR(bbar[i], b[i], 1e-5) << "b_" << i;
  }
}

TEST(Preintegration, EveryTexelIsInRange) {
  const Lut& lut = small_lut();
  for (std::size_t y = 0; y < lut.size; ++y) {
    for (std::size_t x = 0; x < lut.size; ++x) {
      const auto t = lut.view().texel(x, y);
      // Weights G2/G1 lie in [0, 1] and |b_i| <= 1, b_1 in [0, 1].
      EXPECT_GT(t[0], 0.0f);
      EXPECT_LE(t[0], 1.0f + 1e-6f);
      EXPECT_GE(t[1], 0.0f);
      EXPECT_LE(t[1], t[0] + 1e-6f);
      EXPECT_LE(std::abs(t[2]), t[0] + 1e-6f);
      EXPECT_LE(std::abs(t[3]), t[0] + 1e-6f);
    }
  }
}

// Directional albedo E = integral of D G2 / (4 mu_o mu_i) mu_i over the hemisphere, integrated by
// brute force (stratified uniform directions, the GGX D written out): an estimator that shares
// nothing with the visible-normal sampler.
double brute_force_albedo(double mu_o, double roughness) {
  const double alpha2 = std::pow(roughness, 4.0);
  const double pi = std::numbers::pi;
  const auto lambda = [&](double c) {
    return 0.5 * (-1.0 + std::sqrt(1.0 + alpha2 * (1.0 - c * c) / (c * c)));
  };
  const double view_x = std::sqrt(1.0 - mu_o * mu_o);
  const int n = 600;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double mu_i = (i + 0.5) / n;  // uniform in cos(theta_i): pdf 1 / (2 pi)
      const double phi = 2.0 * pi * (j + 0.5) / n;
      const double sin_i = std::sqrt(1.0 - mu_i * mu_i);
      const double hx = view_x + sin_i * std::cos(phi);
      const double hy = sin_i * std::sin(phi);
      const double hz = mu_o + mu_i;
      const double cos2_h = hz * hz / (hx * hx + hy * hy + hz * hz);
      const double d = alpha2 / (pi * std::pow(cos2_h * (alpha2 - 1.0) + 1.0, 2.0));
      const double g2 = 1.0 / (1.0 + lambda(mu_o) + lambda(mu_i));
      sum += d * g2 / (4.0 * mu_o) * 2.0 * pi;
    }
  }
  return sum / (n * n);
}

TEST(Preintegration, AlbedoMatchesBruteForceIntegrationOfTheBrdf) {
  for (const double roughness : {0.5, 1.0}) {
    for (const double mu : {0.1, 0.5, 0.9}) {
      EXPECT_NEAR(preintegrate_basis(kBasis, mu, roughness, 16384)[0],
                  brute_force_albedo(mu, roughness), 1e-3)
          << "mu=" << mu << " roughness=" << roughness;
    }
  }
}

TEST(Preintegration, BytesDoNotDependOnTheThreadCount) {
  const Lut one = preintegrate_lut(kBasis, {24, 128, 1});
  const Lut three = preintegrate_lut(kBasis, {24, 128, 3});
  const Lut again = preintegrate_lut(kBasis, {24, 128, 3});
  EXPECT_EQ(one.texels, three.texels);
  EXPECT_EQ(three.texels, again.texels);
}

// The same grid as the accuracy study's sampling-error line (docs/accuracy.md); the bound holds it.
TEST(Preintegration, ConvergesToAHighSampleReference) {
  double worst = 0.0;
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      const double mu = std::pow(i / 8.0, 2);
      const double roughness = j / 8.0;
      const auto coarse = preintegrate_basis(kBasis, mu, roughness, 1024);
      const auto fine = preintegrate_basis(kBasis, mu, roughness, 65536);
      for (std::size_t c = 0; c < 4; ++c)
        worst = std::max(worst, std::abs(coarse[c] - fine[c]));
    }
  }
  EXPECT_LT(worst, 0.002);
}

class SchlickCurve final : public ReflectanceCurve {
 public:
  explicit SchlickCurve(double f0) : f0_(f0) {}
  Rgb at(double mu) const override {
    const double f = fresnel_schlick(mu, f0_);
    return {f, f, f};
  }

 private:
  double f0_;
};

// Karis' table is the split sum of Schlick's basis {1, (1 - mu)^5}: Fbar = F0 A + B with
// A = bbar_s0 - bbar_s1 and B = bbar_s1. Our basis reproduces Schlick curves to within their fit
// error, and the split sum (a weighted average with weights in [0, 1] over the same samples) cannot
// amplify that error, so the difference is bounded by it.
TEST(Preintegration, SumMatchesKarisTwoTermTableForSchlickCurves) {
  const std::size_t n = kBasis.samples();
  std::vector<double> schlick_lobe(n);
  std::vector<double> zero(n, 0.0);
  for (std::size_t j = 0; j < n; ++j)
    schlick_lobe[j] = std::pow(1.0 - kBasis.mu_at(j), 5.0);
  const runtime::BasisView schlick_basis{{schlick_lobe, zero, zero}, {1, 2}};
  for (const double f0 : {0.04, 0.5, 0.9}) {
    const SchlickCurve curve(f0);
    const auto c = solve_coefficients(curve, kBasis);
    const double fit_error =
        measure_accuracy(curve, c, runtime::shipped_shader_basis(matc::runtime::BasisKind::paper))
            .decomposition.max_abs[0];
    for (const double mu : {0.05, 0.4, 0.9}) {
      for (const double roughness : {0.1, 0.5, 0.9}) {
        const auto ours = preintegrate_basis(kBasis, mu, roughness, 1024);
        const auto karis = preintegrate_basis(schlick_basis, mu, roughness, 1024);
        const double a = karis[0] - karis[1];
        const double b = karis[1];
        double fbar = 0.0;
        for (std::size_t i = 0; i < 4; ++i)
          fbar += c[0][i] * ours[i];
        EXPECT_LE(std::abs(fbar - (f0 * a + b)), fit_error + 1e-6)
            << "F0=" << f0 << " mu=" << mu << " roughness=" << roughness;
      }
    }
  }
}

TEST(Preintegration, RejectsSizesAndSampleCountsOutsideTheLimits) {
  EXPECT_THROW(preintegrate_lut(kBasis, {1, 16, 1}), std::invalid_argument);
  EXPECT_THROW(preintegrate_lut(kBasis, {kMaxLutSize + 1, 16, 1}), std::invalid_argument);
  EXPECT_THROW(preintegrate_lut(kBasis, {8, 0, 1}), std::invalid_argument);
}

TEST(LutSampling, TexelCentresAreExactAndBetweenThemIsBilinear) {
  const runtime::LutView lut = small_lut().view();
  const double last = static_cast<double>(lut.size - 1);
  for (const std::size_t x : {std::size_t{0}, std::size_t{7}, lut.size - 1}) {
    for (const std::size_t y : {std::size_t{0}, std::size_t{13}, lut.size - 1}) {
      const double u = static_cast<double>(x) / last;
      const double roughness = static_cast<double>(y) / last;
      const auto sampled = runtime::sample_lut(lut, runtime::lut_ndotv_from_u(u), roughness);
      const auto texel = lut.texel(x, y);
      for (std::size_t i = 0; i < 4; ++i)
        EXPECT_NEAR(sampled[i], texel[i], 1e-6);
    }
  }
  const auto middle = runtime::sample_lut(lut, runtime::lut_ndotv_from_u(3.5 / last), 5.5 / last);
  for (std::size_t i = 0; i < 4; ++i) {
    const double average =
        (lut.texel(3, 5)[i] + lut.texel(4, 5)[i] + lut.texel(3, 6)[i] + lut.texel(4, 6)[i]) / 4.0;
    EXPECT_NEAR(middle[i], average, 1e-6);
  }
}

TEST(Energy, BasisAveragesAreExactIntegrals) {
  const auto m = basis_hemispherical_averages(kBasis);
  EXPECT_NEAR(m[0], 1.0, 1e-12);
  // Midpoint rule on a much finer grid than the basis.
  std::array<double, 4> numeric{};
  const int steps = 200000;
  for (int k = 0; k < steps; ++k) {
    const double mu = (k + 0.5) / steps;
    const auto b = kBasis.evaluate(mu);
    for (std::size_t i = 0; i < 4; ++i)
      numeric[i] += 2.0 * b[i] * mu / steps;
  }
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NEAR(m[i], numeric[i], 1e-8) << "m_" << i;
}

TEST(Energy, AverageAlbedoIsOneForMirrorsAndFallsWithRoughness) {
  const std::vector<double> e_avg = average_albedo(small_lut());
  EXPECT_NEAR(e_avg.front(), 1.0, 2e-3);
  EXPECT_TRUE(std::is_sorted(e_avg.rbegin(), e_avg.rend()));
  EXPECT_LT(e_avg.back(), 0.8);
}

// Bounded by the curve fit error (0.0191 worst, docs/accuracy.md) plus the table's reconstruction
// and sampling error; the accuracy study reports the measured value over all metals.
TEST(Fbar, TableFollowsTheDirectReferenceOnMeasuredMetals) {
  const Lut lut = preintegrate_lut(kBasis, {});
  double worst = 0.0;
  for (const char* symbol : {"Au", "Cr", "Be", "Hg", "Rh"}) {
    const TabulatedCurve curve(SpectralCurve(preset_spectrum(*find_metal_preset(symbol))));
    const auto c = solve_coefficients(curve, kBasis);
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        const double mu = (i + 0.5) / 6.0;
        const double roughness = (j + 0.5) / 6.0;
        const Rgb fbar = runtime::evaluate_fbar(c, lut.view(), mu, roughness);
        const Rgb reference = SplitSumEstimator(mu, roughness, 8192).integrate(curve);
        for (std::size_t ch = 0; ch < 3; ++ch) {
          worst = std::max(worst, std::abs(fbar[ch] - reference[ch]));
        }
      }
    }
  }
  EXPECT_LT(worst, 0.02);
}

// The checked-in hashes are those of the tables baked today, for every basis, format and
// precision (rerun `matc basis lut-hashes -o compiler/src/generated/default_lut_hashes.cpp`), and
// only the default size and sample count have one.
TEST(DefaultLutHashes, CheckedInHashesAreCurrent) {
  const std::vector<DefaultLutHash> computed = compute_default_lut_hashes();
  const std::vector<DefaultLutHash> checked_in = checked_in_default_lut_hashes();
  ASSERT_EQ(computed.size(), checked_in.size());
  // Every basis in 4 formats and 2 precisions, and the per-material build's layered table.
  ASSERT_EQ(computed.size(), (runtime::kShippedBases.size() + 1) * 4 * 2);
  for (std::size_t i = 0; i < computed.size(); ++i) {
    EXPECT_EQ(checked_in[i].hash, computed[i].hash)
        << runtime::basis_name(computed[i].basis) << " " << lut_format_name(computed[i].format)
        << " " << lut_precision_name(computed[i].precision)
        << (computed[i].layered ? " layered" : "");
    EXPECT_EQ(checked_in[i].layered, computed[i].layered);
    EXPECT_EQ(default_lut_hash(computed[i].basis, computed[i].format, computed[i].precision, {},
                               computed[i].layered),
              computed[i].hash);
  }
  EXPECT_FALSE(
      default_lut_hash(runtime::kDefaultBasis, LutFormat::ktx2, LutPrecision::f32, {.size = 64}));
  EXPECT_FALSE(default_lut_hash(runtime::kDefaultBasis, LutFormat::ktx2, LutPrecision::f32,
                                {.samples = 512}));
}

}  // namespace
}  // namespace matc
