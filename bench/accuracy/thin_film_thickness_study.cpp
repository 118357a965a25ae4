// What could a shader evaluate for a film whose thickness varies per pixel (issue #67, glTF's
// iridescenceThicknessTexture; docs/accuracy.md "A thickness per pixel")? A table over the
// thickness cannot hold the fringes (matc_thin_film_table_study), so the thickness has to enter
// the shader's arithmetic. This measures the candidates against the spectral Airy sum.
//
// Per polarisation, with a = r01 (real: the film's index is real) and b = r12 (complex: the
// metal), the Airy reflectance is a Fourier series in the film's phase delta = 2 pi X / lambda,
// X = 2 d q1 the optical path difference:
//   R = C0 + 2 Re sum_{m>=1} C_m e^{i m delta},   C_m = K s^{m-1},   s = -a b,
//   C0 = a^2 + (1 - a^2)^2 |b|^2 / (1 - a^2 |b|^2),  K = a b (1 - a^2)(1 - |b|^2) / (1 - a^2 |b|^2)
// (summed: R = C0 + 2 Re K z / (1 - s z), z = e^{i delta}). A channel c is the sum over the
// wavelengths with the spectral weights w_c. The candidates (columns):
//   - `M orders`: the series cut after M orders, each order's sum over the spectrum exact (a
//     table of it over the cosine and X per order). The structure of Belcour and Barla's 2017
//     model, which the engines' KHR_materials_iridescence evaluates with M = 2 (and with a
//     dielectric base); here only the cut is approximate.
//   - `channel mean`: 8 orders, each order's spectral sum as P_cm e^{i 2 pi m X nu_c} g_c(m X)
//     with P_cm = sum_l w_c C_m (a table over the cosine), nu_c = sum_l w_c / l (the carrier,
//     computed in the shader) and g_c(X) = sum_l w_c e^{i 2 pi X (1 / l - nu_c)} (the channel's
//     envelope, the same for every material). Exact if C_m were constant over the channel.
//   - `J sub-bands`: the spectrum cut into J bands of equal weight (sum of |w_c| over the
//     channels), each with its channel weights, mean wavenumber nu_j, spread sigma_j and the
//     metal's index at 1 / nu_j: the closed form at nu_j with z damped by
//     exp(-2 pi^2 sigma_j^2 X^2) for the band's loss of coherence (J complex Airy sums per
//     polarisation in the shader, the indices as material constants).
//   - `16 indices, every wavelength`: the 16 sub-bands' indices, but every wavelength's phase:
//     what holding the metal's index constant over a sub-band costs by itself.
//   - `8 orders + damped tail`: 8 orders as above, and the orders past 8 from the 16 sub-bands'
//     closed form (K s^8 z^9 / (1 - s z) per band), scaled by the channel's coherence at 9 X,
//     |g_c(9 X)|: kept where the film is thin (where the sub-bands hold), dropped where it is
//     thick (where the orders alone hold).
// Each cell: the worst |candidate - spectral Airy sum| over the 23 reliable measured metals, the
// channels, 40 cosines in [0.05, 1] / in [0.2, 1], and thicknesses every 5 nm in the row's band.
//   build/bench/matc_thin_film_thickness_study   (about 3 minutes on 2 cores;
//   bench/accuracy/update-docs.sh)
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <future>
#include <numbers>
#include <string_view>
#include <vector>

#include <fmt/core.h>

#include "optics/presets.h"
#include "optics/spectral.h"
#include "optics/thin_film.h"

namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

constexpr std::array<double, 4> kIndices = {1.2, 1.5, 2.0, 2.5};
struct ThicknessBand {
  int first_nm, last_nm;
};
// glTF's default thickness range is 100-400 nm.
constexpr std::array<ThicknessBand, 3> kBands = {{{0, 100}, {105, 400}, {405, 1000}}};
constexpr int kCosines = 40;
double cosine_at(int j) {
  return 0.05 + 0.95 * j / (kCosines - 1);
}

enum Candidate : std::size_t {
  orders_2,
  orders_4,
  orders_8,
  channel_mean,
  sub_bands_8,
  sub_bands_16,
  sub_band_indices,
  sub_bands_16_per_order,
  hybrid,
  kCandidates
};
constexpr std::array<std::string_view, kCandidates> kNames = {"2 orders",
                                                              "4 orders",
                                                              "8 orders",
                                                              "channel mean",
                                                              "8 sub-bands",
                                                              "16 sub-bands",
                                                              "16 indices, every wavelength",
                                                              "16 sub-bands, each order damped",
                                                              "8 orders + damped tail"};
constexpr int kMaxOrder = 8;

struct Series {
  double c0 = 0.0;
  Complex k;
  Complex s;

  Series() = default;
  Series(double a, Complex b) {
    const double b2 = std::norm(b), denominator = 1.0 - a * a * b2;
    c0 = a * a + (1.0 - a * a) * (1.0 - a * a) * b2 / denominator;
    k = a * b * (1.0 - a * a) * (1.0 - b2) / denominator;
    s = -a * b;
  }
  // The whole sum at z (|z| <= 1; below 1 for a damped phase).
  double at(Complex z) const { return c0 + 2.0 * std::real(k * z / (1.0 - s * z)); }
};

// Both polarisations' series at one cosine for a metal of index eta under a film of index n1.
struct Polarisations {
  Series s_wave, p_wave;

  Polarisations(double mu, double n1, Complex eta) {
    const double sin2 = 1.0 - mu * mu, q1 = std::sqrt(n1 * n1 - sin2);
    const Complex q2 = std::sqrt(eta * eta - sin2);
    s_wave = Series((mu - q1) / (mu + q1), (q1 - q2) / (q1 + q2));
    p_wave = Series((n1 * n1 * mu - q1) / (n1 * n1 * mu + q1),
                    (eta * eta * q1 - n1 * n1 * q2) / (eta * eta * q1 + n1 * n1 * q2));
  }
  double at(Complex z) const { return 0.5 * (s_wave.at(z) + p_wave.at(z)); }
};

struct SubBand {
  std::size_t first = 0, last = 0;  // its wavelengths on the grid, [first, last)
  std::array<double, 3> weight{};
  double nu = 0.0, sigma = 0.0;
  Complex eta;
};

double wavelength_at(std::size_t l) {
  return matc::kCieFirstNm + static_cast<double>(l);
}

std::vector<SubBand> sub_bands(const matc::Spectrum& metal, std::size_t count) {
  const std::vector<matc::Rgb>& w = matc::spectral_weights(matc::kDefaultColorSpace);
  std::vector<double> mass(w.size());
  double total = 0.0;
  for (std::size_t l = 0; l < w.size(); ++l)
    total += mass[l] = std::abs(w[l][0]) + std::abs(w[l][1]) + std::abs(w[l][2]);
  std::vector<SubBand> bands(count);
  std::vector<double> band_mass(count), nu2(count);
  double cumulative = 0.0;
  for (std::size_t l = 0; l < w.size(); ++l) {
    const auto j =
        std::min(count - 1, static_cast<std::size_t>((cumulative + 0.5 * mass[l]) / total *
                                                     static_cast<double>(count)));
    cumulative += mass[l];
    if (bands[j].last == 0) bands[j].first = l;
    bands[j].last = l + 1;
    const double nu = 1.0 / wavelength_at(l);
    for (std::size_t c = 0; c < 3; ++c)
      bands[j].weight[c] += w[l][c];
    bands[j].nu += mass[l] * nu;
    nu2[j] += mass[l] * nu * nu;
    band_mass[j] += mass[l];
  }
  for (std::size_t j = 0; j < count; ++j) {
    bands[j].nu /= band_mass[j];
    bands[j].sigma = std::sqrt(std::max(0.0, nu2[j] / band_mass[j] - bands[j].nu * bands[j].nu));
    bands[j].eta = metal.at(1.0 / bands[j].nu).eta();
  }
  return bands;
}

// errors[candidate][thickness band][0: cosines 0.05-1, 1: 0.2-1]
using Errors = std::array<std::array<std::array<double, 2>, kBands.size()>, kCandidates>;

Errors measure(const matc::Spectrum& metal, double n1) {
  const std::vector<matc::Rgb>& w = matc::spectral_weights(matc::kDefaultColorSpace);
  const std::size_t lambdas = w.size();
  std::array<double, 3> nu_c{};
  for (std::size_t l = 0; l < lambdas; ++l)
    for (std::size_t c = 0; c < 3; ++c)
      nu_c[c] += w[l][c] / wavelength_at(l);
  const std::array<std::vector<SubBand>, 2> quadratures = {sub_bands(metal, 8),
                                                           sub_bands(metal, 16)};
  Errors errors{};
  for (int j = 0; j < kCosines; ++j) {
    const double mu = cosine_at(j), q1 = std::sqrt(n1 * n1 - (1.0 - mu * mu));
    std::vector<Polarisations> at;
    at.reserve(lambdas);
    std::array<double, 3> c0{};
    std::array<std::array<Complex, kMaxOrder + 1>, 3> p{};  // P_cm
    for (std::size_t l = 0; l < lambdas; ++l) {
      at.emplace_back(mu, n1, metal.at(wavelength_at(l)).eta());
      for (const Series* pol : {&at[l].s_wave, &at[l].p_wave}) {
        Complex cm = pol->k;
        for (std::size_t c = 0; c < 3; ++c)
          c0[c] += w[l][c] * 0.5 * pol->c0;
        for (std::size_t m = 1; m <= kMaxOrder; ++m, cm *= pol->s)
          for (std::size_t c = 0; c < 3; ++c)
            p[c][m] += w[l][c] * 0.5 * cm;
      }
    }
    std::array<std::vector<Polarisations>, 2> band_series;
    for (std::size_t q = 0; q < 2; ++q)
      for (const SubBand& band : quadratures[q])
        band_series[q].emplace_back(mu, n1, band.eta);

    for (std::size_t b = 0; b < kBands.size(); ++b) {
      for (int thickness = kBands[b].first_nm; thickness <= kBands[b].last_nm; thickness += 5) {
        const double x = 2.0 * thickness * q1;
        std::array<double, 3> exact{};
        std::array<std::array<double, kMaxOrder + 1>, 3> partial{};    // C0 + orders <= m
        std::array<std::array<Complex, kMaxOrder + 1>, 3> envelope{};  // g_c(m X)
        for (std::size_t l = 0; l < lambdas; ++l) {
          const double nu = 1.0 / wavelength_at(l);
          const Complex z = std::polar(1.0, kTwoPi * x * nu);
          const double r = at[l].at(z);
          std::array<double, kMaxOrder + 1> orders{};
          for (const Series* pol : {&at[l].s_wave, &at[l].p_wave}) {
            Complex term = pol->k * z;
            for (std::size_t m = 1; m <= kMaxOrder; ++m, term *= pol->s * z)
              orders[m] += std::real(term);  // 0.5 x 2 Re
          }
          for (std::size_t c = 0; c < 3; ++c) {
            exact[c] += w[l][c] * r;
            double sum = 0.0;
            for (std::size_t m = 1; m <= kMaxOrder; ++m) {
              sum += orders[m];
              partial[c][m] += w[l][c] * sum;
              envelope[c][m] +=
                  w[l][c] * std::polar(1.0, kTwoPi * static_cast<double>(m) * x * (nu - nu_c[c]));
            }
          }
        }
        std::array<std::array<double, 3>, kCandidates> value{};
        for (std::size_t c = 0; c < 3; ++c) {
          value[orders_2][c] = c0[c] + partial[c][2];
          value[orders_4][c] = c0[c] + partial[c][4];
          value[orders_8][c] = c0[c] + partial[c][8];
          value[channel_mean][c] = c0[c];
          for (std::size_t m = 1; m <= kMaxOrder; ++m) {
            const Complex carrier = std::polar(1.0, kTwoPi * static_cast<double>(m) * x * nu_c[c]);
            value[channel_mean][c] += 2.0 * std::real(p[c][m] * carrier * envelope[c][m]);
          }
        }
        std::array<double, 3> tail_c{};
        for (std::size_t q = 0; q < 2; ++q) {
          for (std::size_t i = 0; i < quadratures[q].size(); ++i) {
            const SubBand& band = quadratures[q][i];
            const double coherence = std::exp(-0.5 * std::pow(kTwoPi * band.sigma * x, 2));
            const double r =
                band_series[q][i].at(coherence * std::polar(1.0, kTwoPi * x * band.nu));
            for (std::size_t c = 0; c < 3; ++c)
              value[q == 0 ? sub_bands_8 : sub_bands_16][c] += band.weight[c] * r;
            if (q == 1) {
              const Complex zd = coherence * std::polar(1.0, kTwoPi * x * band.nu);
              double tail = 0.0;
              for (const Series* pol : {&band_series[q][i].s_wave, &band_series[q][i].p_wave})
                tail += std::real(pol->k * std::pow(pol->s, kMaxOrder) *
                                  std::pow(zd, kMaxOrder + 1) / (1.0 - pol->s * zd));
              for (std::size_t c = 0; c < 3; ++c)
                tail_c[c] += band.weight[c] * tail;
            }
            if (q == 1) {
              // Each order m damped by the band's coherence at m X, the tail past 8 as above.
              double per_order = 0.0;
              const Complex z = std::polar(1.0, kTwoPi * x * band.nu);
              for (const Series* pol : {&band_series[q][i].s_wave, &band_series[q][i].p_wave}) {
                double sum = pol->c0;
                Complex term = pol->k * z;
                for (int m = 1; m <= kMaxOrder; ++m, term *= pol->s * z)
                  sum += 2.0 * std::real(term) *
                         std::exp(-0.5 * std::pow(kTwoPi * band.sigma * m * x, 2));
                const Complex zd = coherence * z;
                Complex tail = pol->k * std::pow(pol->s, kMaxOrder) * std::pow(zd, kMaxOrder + 1) /
                               (1.0 - pol->s * zd);
                sum += 2.0 * std::real(tail);
                per_order += 0.5 * sum;
              }
              for (std::size_t c = 0; c < 3; ++c)
                value[sub_bands_16_per_order][c] += band.weight[c] * per_order;
              for (std::size_t l = band.first; l < band.last; ++l) {
                const double rl =
                    band_series[q][i].at(std::polar(1.0, kTwoPi * x / wavelength_at(l)));
                for (std::size_t c = 0; c < 3; ++c)
                  value[sub_band_indices][c] += w[l][c] * rl;
              }
            }
          }
        }
        for (std::size_t c = 0; c < 3; ++c)
          value[hybrid][c] =
              c0[c] + partial[c][kMaxOrder] + std::abs(envelope[c][kMaxOrder]) * tail_c[c];
        for (std::size_t candidate = 0; candidate < kCandidates; ++candidate) {
          for (std::size_t c = 0; c < 3; ++c) {
            const double error = std::abs(value[candidate][c] - exact[c]);
            auto& cell = errors[candidate][b];
            cell[0] = std::max(cell[0], error);
            if (mu >= 0.2) cell[1] = std::max(cell[1], error);
          }
        }
      }
    }
  }
  return errors;
}

// The series against thin_film_reflectance, the reference the compiler is held to.
double series_check() {
  double worst = 0.0;
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    const matc::Spectrum& metal = matc::preset_spectrum(preset);
    for (const double mu : {0.05, 0.5, 1.0})
      for (const double nm : {400.0, 550.0, 700.0}) {
        const Polarisations series(mu, 2.0, metal.at(nm).eta());
        const double x = 2.0 * 300.0 * std::sqrt(4.0 - (1.0 - mu * mu));
        worst = std::max(worst,
                         std::abs(series.at(std::polar(1.0, kTwoPi * x / nm)) -
                                  matc::thin_film_reflectance(mu, nm, {2.0, 300.0}, metal.at(nm))));
      }
  }
  return worst;
}

}  // namespace

int main() {
  if (const double check = series_check(); check > 1e-9) {
    fmt::print(stderr, "the series is {:.1e} from thin_film_reflectance\n", check);
    return 1;
  }
  std::vector<const matc::Spectrum*> metals;
  for (const matc::MetalPreset& preset : matc::metal_presets())
    if (preset.caveat.empty()) metals.push_back(&matc::preset_spectrum(preset));
  fmt::print("| film index | thickness |");
  for (const std::string_view name : kNames)
    fmt::print(" {} |", name);
  fmt::print("\n|---:|---|");
  for (std::size_t i = 0; i < kCandidates; ++i)
    fmt::print("---:|");
  fmt::print("\n");
  for (const double index : kIndices) {
    std::vector<std::future<Errors>> futures;
    for (const matc::Spectrum* metal : metals)
      futures.push_back(std::async(std::launch::async, measure, std::cref(*metal), index));
    Errors worst{};
    for (auto& future : futures) {
      const Errors errors = future.get();
      for (std::size_t candidate = 0; candidate < kCandidates; ++candidate)
        for (std::size_t b = 0; b < kBands.size(); ++b)
          for (std::size_t range = 0; range < 2; ++range)
            worst[candidate][b][range] =
                std::max(worst[candidate][b][range], errors[candidate][b][range]);
    }
    for (std::size_t b = 0; b < kBands.size(); ++b) {
      fmt::print("| {:.1f} | {}-{} nm |", index, kBands[b].first_nm, kBands[b].last_nm);
      for (std::size_t candidate = 0; candidate < kCandidates; ++candidate)
        fmt::print(" {:.3f} / {:.3f} |", worst[candidate][b][0], worst[candidate][b][1]);
      fmt::print("\n");
    }
  }
  return 0;
}
