// A film over a metal known only in RGB (Gulbrandsen's r and g, n and k per channel, F82-tint,
// glTF's F0): which complex index and which wavelengths should a channel's film curve use, and what
// does that cost against the spectral truth (issue #67, docs/accuracy.md "A film over an RGB
// metal")? For titanium, gold, copper, iron and chromium, each channel's (n, k) is
//   - Gulbrandsen's conductor of the bare curve's look (gulbrandsen_look.h: what an artist's r and
//     g would be; `artistic`, F82-tint and glTF's F0 reach an index this way), or
//   - the measured index at the channel's centroid wavelength (sum_l l w_c(l) / sum_l w_c(l)), what
//     an `ior` material's n and k per channel would be,
// and the film over it is the Airy sum either at the centroid alone (one wavelength a channel) or
// at every wavelength with the channel's (n, k), weighted by w_c(l) as spectral curves are reduced
// (the channel's band: a bake-time sum, so the shader's table costs the same). Each cell is the
// worst |approximation - spectral film curve| over the metals, channels and cosines in
// [0.05, 1]; the thickness-0 row is the bare per-channel index alone.
//   build/bench/matc_thin_film_rgb_study   (about 20 s on 2 cores; bench/accuracy/update-docs.sh)
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "gulbrandsen_look.h"
#include "optics/fresnel.h"
#include "optics/gulbrandsen.h"
#include "optics/presets.h"
#include "optics/spectral.h"
#include "optics/thin_film.h"

namespace {

constexpr std::array<std::string_view, 5> kMetals = {"Ti", "Au", "Cu", "Fe", "Cr"};
constexpr std::array<double, 4> kIndices = {1.33, 1.5, 2.0, 2.5};
constexpr std::array<double, 8> kThicknesses = {0, 50, 100, 200, 350, 500, 800, 1000};

double checked_cosine(int j) {
  return 0.05 + 0.01 * j;  // 96 cosines, 0.05 to 1
}

// Each channel's Gulbrandsen conductor: the look of the bare curve (its reflectivity held below 1,
// where Gulbrandsen's mapping has a conductor).
std::array<matc::ComplexIor, 3> channel_indices(const matc::ReflectanceCurve& bare) {
  const auto look = matc::bench::gulbrandsen_look(bare, 0.999);
  return {matc::gulbrandsen_to_ior(look[0]), matc::gulbrandsen_to_ior(look[1]),
          matc::gulbrandsen_to_ior(look[2])};
}

struct Errors {
  double gulbrandsen_one_wavelength = 0.0;
  double gulbrandsen_band = 0.0;
  double measured_band = 0.0;
};

Errors measure(double index, double thickness) {
  const std::vector<matc::Rgb>& weights = matc::spectral_weights(matc::kDefaultColorSpace);
  // The centroid wavelength of each channel's weights.
  std::array<double, 3> centroid{};
  for (std::size_t c = 0; c < 3; ++c) {
    double sum = 0.0, moment = 0.0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
      sum += weights[i][c];
      moment += weights[i][c] * static_cast<double>(matc::kCieFirstNm + static_cast<int>(i));
    }
    centroid[c] = moment / sum;
  }
  const matc::ThinFilm film{index, thickness};
  Errors errors;
  for (const std::string_view symbol : kMetals) {
    const matc::Spectrum& metal = matc::preset_spectrum(*matc::find_metal_preset(symbol));
    const matc::SpectralCurve bare(metal);
    const std::array<matc::ComplexIor, 3> ior = channel_indices(bare);
    const std::array<matc::ComplexIor, 3> measured = {metal.at(centroid[0]), metal.at(centroid[1]),
                                                      metal.at(centroid[2])};
    const matc::ThinFilmCurve exact(metal, film);
    for (int j = 0; j <= 95; ++j) {
      const double mu = checked_cosine(j);
      const matc::Rgb truth = exact.at(mu);
      for (std::size_t c = 0; c < 3; ++c) {
        const double one = matc::thin_film_reflectance(mu, centroid[c], film, ior[c]);
        double band = 0.0, measured_band = 0.0;
        for (std::size_t i = 0; i < weights.size(); ++i) {
          const double nm = static_cast<double>(matc::kCieFirstNm + static_cast<int>(i));
          band += weights[i][c] * matc::thin_film_reflectance(mu, nm, film, ior[c]);
          measured_band += weights[i][c] * matc::thin_film_reflectance(mu, nm, film, measured[c]);
        }
        errors.gulbrandsen_one_wavelength =
            std::max(errors.gulbrandsen_one_wavelength, std::abs(one - truth[c]));
        errors.gulbrandsen_band = std::max(errors.gulbrandsen_band, std::abs(band - truth[c]));
        errors.measured_band = std::max(errors.measured_band, std::abs(measured_band - truth[c]));
      }
    }
  }
  return errors;
}

}  // namespace

int main() {
  std::vector<std::future<Errors>> rows;
  for (const double index : kIndices)
    for (const double thickness : kThicknesses)
      rows.push_back(std::async(std::launch::async, measure, index, thickness));
  fmt::print(
      "| film: index, thickness | Gulbrandsen (r, g), one wavelength a channel | Gulbrandsen (r, "
      "g), "
      "the channel's band | measured n, k at the channel's centroid, the channel's band |\n"
      "|---|---:|---:|---:|\n");
  std::size_t next = 0;
  for (const double index : kIndices) {
    for (const double thickness : kThicknesses) {
      const Errors errors = rows[next++].get();
      fmt::print("| {:.2f}, {:.0f} nm | {:.4f} | {:.4f} | {:.4f} |\n", index, thickness,
                 errors.gulbrandsen_one_wavelength, errors.gulbrandsen_band, errors.measured_band);
    }
  }
  return 0;
}
