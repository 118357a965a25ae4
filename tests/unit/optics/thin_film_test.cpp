// A thin dielectric film over a conductor (optics/thin_film.h), the physics issue #67 builds on:
// against the bare metal where the film vanishes, against an independent method (Born and Wolf's
// characteristic matrix), and on measured spectra.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

#include "optics/presets.h"
#include "optics/reflectance_curve.h"
#include "optics/spectral.h"
#include "optics/thin_film.h"

namespace {

using matc::ComplexIor;
using matc::ThinFilm;
using Complex = std::complex<double>;

// Metals at one wavelength (gold, titanium and silver near 550 nm, and a weak absorber).
constexpr std::array<ComplexIor, 4> kMetals = {
    {{0.43, 2.46}, {2.54, 3.43}, {0.06, 3.59}, {1.8, 0.05}}};
constexpr std::array<double, 6> kCosines = {1.0, 0.8, 0.5, 0.3, 0.1, 0.02};

// Born and Wolf's characteristic matrix of one layer (Principles of Optics, 1.6), for the
// e^{-i omega t} convention: M = [[cos b, -i sin b / p1], [-i p1 sin b, cos b]] with b the film's
// phase thickness 2 pi d n1 cos(theta_1) / lambda and p_j the polarisation's admittance
// (n_j cos(theta_j) for s, cos(theta_j) / n_j for p). r = (p0 B - C) / (p0 B + C) with
// (B, C) = M (1, p2). A derivation of its own: no Airy sum, no interface amplitudes, no relative
// indices. `ambient` is the index of the medium the light comes from (a coat), `mu` the cosine in
// it; beyond a film's critical angle cos1 is imaginary, and M does not depend on its root's sign.
double characteristic_matrix_reflectance(double mu, double wavelength, const ThinFilm& film,
                                         ComplexIor metal, double ambient = 1.0) {
  const double invariant2 = ambient * ambient * (1.0 - mu * mu);  // (n0 sin theta_0)^2
  const Complex n0 = ambient, n1 = film.ior, n2 = metal.eta();
  const Complex cos0 = mu;
  const Complex cos1 = std::sqrt(1.0 - invariant2 / (n1 * n1));
  const Complex cos2 = std::sqrt(n2 * n2 - invariant2) / n2;  // the decaying root, as n2 cos2
  const Complex b = 2.0 * std::numbers::pi * film.thickness_nm * n1 * cos1 / wavelength;
  const auto reflectance = [&](Complex p0, Complex p1, Complex p2) {
    const Complex i(0.0, 1.0);
    const Complex B = std::cos(b) - i * std::sin(b) / p1 * p2;
    const Complex C = -i * p1 * std::sin(b) + std::cos(b) * p2;
    return std::norm((p0 * B - C) / (p0 * B + C));
  };
  const double s = reflectance(n0 * cos0, n1 * cos1, n2 * cos2);
  const double p = reflectance(cos0 / n0, cos1 / n1, cos2 / n2);
  return 0.5 * (s + p);
}

TEST(ThinFilm, AFilmOfNoThicknessOrOfIndexOneIsTheBareMetal) {
  for (const ComplexIor metal : kMetals) {
    for (const double mu : kCosines) {
      const double bare = matc::fresnel_exact(mu, metal);
      EXPECT_NEAR(matc::thin_film_reflectance(mu, 550.0, {1.8, 0.0}, metal), bare, 1e-13)
          << metal.n << " " << metal.k << " " << mu;
      EXPECT_NEAR(matc::thin_film_reflectance(mu, 550.0, {1.0, 350.0}, metal), bare, 1e-13);
    }
  }
}

TEST(ThinFilm, AgreesWithTheCharacteristicMatrix) {
  double worst = 0.0;
  for (const ComplexIor metal : kMetals) {
    for (const double mu : kCosines) {
      for (const ThinFilm film : {ThinFilm{1.33, 30.0}, ThinFilm{1.6, 120.0}, ThinFilm{2.3, 350.0},
                                  ThinFilm{2.5, 900.0}}) {
        for (const double wavelength : {380.0, 550.0, 780.0}) {
          const double ours = matc::thin_film_reflectance(mu, wavelength, film, metal);
          const double matrix = characteristic_matrix_reflectance(mu, wavelength, film, metal);
          worst = std::max(worst, std::abs(ours - matrix));
          ASSERT_GE(ours, 0.0);
          ASSERT_LE(ours, 1.0);
        }
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
}

// The film's phase repeats when its optical path grows by a wavelength: a film thicker by
// lambda / (2 n1 cos(theta_1)) reflects the same.
// Under a coat the film is seen from a medium of the coat's index: film_under_coat's relative
// film over the metal's relative index must be the absolute stack, also for a film of lower index
// than the coat's, evanescent beyond its critical angle (a direction that cannot come from air,
// but which the Monte-Carlo layered reference reaches after a rough coat's refraction).
TEST(ThinFilm, SeenFromInsideACoatAgreesWithTheCharacteristicMatrix) {
  double worst = 0.0;
  for (const double coat : {1.5, 2.0}) {
    for (const ComplexIor metal : kMetals) {
      const ComplexIor relative{metal.n / coat, metal.k / coat};
      for (const double mu : kCosines) {
        for (const ThinFilm film : {ThinFilm{1.2, 80.0}, ThinFilm{1.5, 300.0}, ThinFilm{2.3, 350.0},
                                    ThinFilm{1.0, 120.0}}) {
          for (const double wavelength : {380.0, 550.0, 780.0}) {
            const double ours = matc::thin_film_reflectance(
                mu, wavelength, matc::film_under_coat(film, coat), relative);
            const double matrix =
                characteristic_matrix_reflectance(mu, wavelength, film, metal, coat);
            worst = std::max(worst, std::abs(ours - matrix));
            ASSERT_GE(ours, 0.0);
            ASSERT_LE(ours, 1.0);
          }
        }
      }
    }
  }
  // 1.2 under 2.0 has its critical cosine at 0.8, one of the cosines: there both methods divide
  // near-zeros (q_1 = 0), and agree to 3e-9.
  EXPECT_LT(worst, 1e-8);
}

// The curves' fast path holds while the film's wave propagates; past a relative film's critical
// angle they take the reference's complex sum, and must still be its weighted sum.
TEST(ThinFilmCurve, UnderACoatOfHigherIndexIsTheReferencePastTheCriticalAngle) {
  const matc::Spectrum& gold = matc::preset_spectrum(*matc::find_metal_preset("Au"));
  matc::Spectrum relative = gold;
  for (std::size_t i = 0; i < relative.n.size(); ++i) {
    relative.n[i] /= 1.6;
    relative.k[i] /= 1.6;
  }
  const ThinFilm film = matc::film_under_coat({1.3, 200.0, 0.8}, 1.6);
  const matc::ThinFilmCurve curve(relative, film);
  const auto& weights = matc::spectral_weights(matc::kDefaultColorSpace);
  // The critical cosine of 1.3 under 1.6 is sqrt(1 - (1.3 / 1.6)^2) = 0.58.
  for (const double mu : {0.9, 0.6, 0.5, 0.2}) {
    matc::Rgb sum{};
    for (std::size_t i = 0; i < weights.size(); ++i) {
      const double nm = matc::kCieFirstNm + static_cast<double>(i);
      const double f = matc::covered_reflectance(mu, nm, film, relative.at(nm));
      for (std::size_t c = 0; c < 3; ++c)
        sum[c] += weights[i][c] * f;
    }
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(curve.at(mu)[c], sum[c], 1e-13) << mu;
  }
}

TEST(ThinFilm, ThePhaseRepeatsEveryHalfWavelengthOfOpticalPath) {
  const ComplexIor titanium{2.54, 3.43};
  for (const double mu : {1.0, 0.6, 0.2}) {
    const double cos1 = std::sqrt(1.0 - (1.0 - mu * mu) / (2.0 * 2.0));
    const double period = 550.0 / (2.0 * 2.0 * cos1);
    EXPECT_NEAR(matc::thin_film_reflectance(mu, 550.0, {2.0, 200.0}, titanium),
                matc::thin_film_reflectance(mu, 550.0, {2.0, 200.0 + period}, titanium), 1e-12);
  }
}

// On measured spectra, reduced to RGB as bare metals are: no film is the bare curve; a film of
// 350 nm and index 2.3 colours titanium strongly (../shared/notes/thin_film.md's sanity values)
// and leaves silver near its bare curve.
// An RGB metal's film: each channel's band sum with its own index. No film is the conductor to
// rounding (a channel's weights sum to 1), a coverage of one half is the mean of bare and filmed,
// and a film changes the colour.
TEST(ThinFilmChannelCurve, ReducesToTheConductorAndMixesByCoverage) {
  const std::array<ComplexIor, 3> ior = {ComplexIor{2.7, 3.8}, {2.5, 3.4}, {2.2, 3.0}};
  const matc::IorCurve bare(ior);
  const auto space = matc::kDefaultColorSpace;
  const matc::ThinFilmChannelCurve none(ior, {2.3, 0.0}, space);
  const matc::ThinFilmChannelCurve full(ior, {2.3, 120.0}, space);
  const matc::ThinFilmChannelCurve half(ior, {2.3, 120.0, 0.5}, space);
  double furthest = 0.0;
  for (const double mu : kCosines) {
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(none.at(mu)[c], bare.at(mu)[c], 1e-13);
      EXPECT_NEAR(half.at(mu)[c], 0.5 * (bare.at(mu)[c] + full.at(mu)[c]), 1e-13);
      furthest = std::max(furthest, std::abs(full.at(mu)[c] - bare.at(mu)[c]));
    }
  }
  EXPECT_GT(furthest, 0.05);
}

// At grazing every stack reflects everything, a film of index 1 (the air/film interface then
// vanishes, 0 / 0 at mu = 0 in the Airy sum) included.
TEST(ThinFilm, GrazingReflectsEverything) {
  const matc::Spectrum& titanium = matc::preset_spectrum(*matc::find_metal_preset("Ti"));
  const std::array<ComplexIor, 3> ior = {ComplexIor{2.7, 3.8}, {2.5, 3.4}, {2.2, 3.0}};
  for (const ThinFilm film : {ThinFilm{1.0, 45.0}, ThinFilm{2.4, 45.0, 0.5}}) {
    EXPECT_EQ(matc::thin_film_reflectance(0.0, 550.0, film, ior[0]), 1.0);
    EXPECT_EQ(matc::ThinFilmCurve(titanium, film).at(0.0), (matc::Rgb{1.0, 1.0, 1.0}));
    EXPECT_EQ(matc::ThinFilmChannelCurve(ior, film, matc::kDefaultColorSpace).at(0.0),
              (matc::Rgb{1.0, 1.0, 1.0}));
    for (const double mu : {1e-9, 1e-4})
      for (const double f : matc::ThinFilmCurve(titanium, film).at(mu))
        EXPECT_TRUE(std::isfinite(f)) << mu;
  }
}

// The curves evaluate the film per cosine once and per wavelength only what depends on it; they
// must be the reference formula's sum, weighted as spectral curves are reduced.
TEST(ThinFilmCurve, IsTheWeightedSumOfTheReference) {
  const matc::Spectrum& gold = matc::preset_spectrum(*matc::find_metal_preset("Au"));
  const std::array<ComplexIor, 3> ior = {ComplexIor{0.2, 3.5}, {0.5, 2.4}, {1.3, 1.8}};
  const auto& weights = matc::spectral_weights(matc::kDefaultColorSpace);
  for (const ThinFilm film : {ThinFilm{1.33, 90.0}, ThinFilm{2.4, 700.0, 0.3}}) {
    const matc::ThinFilmCurve spectral(gold, film);
    const matc::ThinFilmChannelCurve channels(ior, film, matc::kDefaultColorSpace);
    for (const double mu : kCosines) {
      matc::Rgb spectral_sum{}, channel_sum{};
      for (std::size_t i = 0; i < weights.size(); ++i) {
        const double nm = matc::kCieFirstNm + static_cast<double>(i);
        const double f = matc::covered_reflectance(mu, nm, film, gold.at(nm));
        for (std::size_t c = 0; c < 3; ++c) {
          spectral_sum[c] += weights[i][c] * f;
          channel_sum[c] += weights[i][c] * matc::covered_reflectance(mu, nm, film, ior[c]);
        }
      }
      for (std::size_t c = 0; c < 3; ++c) {
        EXPECT_NEAR(spectral.at(mu)[c], spectral_sum[c], 1e-13) << mu;
        EXPECT_NEAR(channels.at(mu)[c], channel_sum[c], 1e-13) << mu;
      }
    }
  }
}

TEST(ThinFilmCurve, OnMeasuredMetals) {
  const auto* titanium = matc::find_metal_preset("Ti");
  const auto* silver = matc::find_metal_preset("Ag");
  ASSERT_NE(titanium, nullptr);
  ASSERT_NE(silver, nullptr);
  const matc::SpectralCurve bare_titanium(matc::preset_spectrum(*titanium));
  const matc::ThinFilmCurve no_film(matc::preset_spectrum(*titanium), {2.3, 0.0});
  for (const double mu : kCosines) {
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(no_film.at(mu)[c], bare_titanium.at(mu)[c], 1e-12);
  }
  const matc::Rgb filmed =
      matc::ThinFilmCurve(matc::preset_spectrum(*titanium), {2.3, 350.0}).at(1.0);
  const matc::Rgb bare = bare_titanium.at(1.0);
  double furthest = 0.0;
  for (std::size_t c = 0; c < 3; ++c)
    furthest = std::max(furthest, std::abs(filmed[c] - bare[c]));
  EXPECT_GT(furthest, 0.1) << filmed[0] << " " << filmed[1] << " " << filmed[2];
  // Strongly coloured: its channels far apart, where bare titanium is nearly grey.
  EXPECT_GT(*std::max_element(filmed.begin(), filmed.end()) -
                *std::min_element(filmed.begin(), filmed.end()),
            0.1);
  const matc::SpectralCurve bare_silver(matc::preset_spectrum(*silver));
  const matc::ThinFilmCurve filmed_silver(matc::preset_spectrum(*silver), {1.5, 350.0});
  for (const double mu : {1.0, 0.5}) {
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(filmed_silver.at(mu)[c], bare_silver.at(mu)[c], 0.05);
  }
}

}  // namespace
