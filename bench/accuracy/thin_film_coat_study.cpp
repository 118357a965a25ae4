// A film under a coat (issue #67, docs/accuracy.md "A film under a coat"): what the base lobe of
// a filmed metal under a clear coat of index 1.5 is, against its exact layered curve (the film
// seen from the coat, transmitted through the coat, bounced between coat and metal), for matc's
// table and for the shortcuts a renderer without the coat's medium in the film takes. Each cell
// is the worst |F_base - exact| over the 23 reliable measured metals, the channels and cosines
// 0.05-1 (every 0.01), thicknesses every 25 nm in the row's band:
//   - ours: the 65-node table of the exact layered base, read as the shaders read it;
//   - the film in air, attenuated once by the coat (1 - F_coat): glTF's layering of a clear coat
//     over KHR_materials_iridescence, with the film's Airy sum exact (the engines' own film adds
//     its dielectric base and two orders on top; docs/accuracy.md "Thin films over metals");
//   - the film in air refracted into the coat: the coat's transmission and bounces exact, but the
//     film's reflectance taken from air at the refracted angle (what a coated metal's layering
//     makes of a film it does not know is under the coat);
//   - the coated metal without its film: what matc compiled before a film could lie under a coat.
//   build/bench/matc_thin_film_coat_study   (about a minute on 2 cores;
//   bench/accuracy/update-docs.sh)
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <vector>

#include <fmt/core.h>

#include "matc/runtime/film_table.h"
#include "optics/coat.h"
#include "optics/presets.h"
#include "optics/spectral.h"
#include "optics/thin_film.h"

namespace {

constexpr double kCoatIor = 1.5;
constexpr std::array<double, 4> kIndices = {1.33, 1.5, 2.0, 2.4};
constexpr std::array<std::array<double, 2>, 3> kBands = {
    {{0.0, 100.0}, {125.0, 400.0}, {425.0, 1000.0}}};
constexpr std::size_t kColumns = 4;
using Errors = std::array<double, kColumns>;

matc::Spectrum relative_to_coat(matc::Spectrum spectrum) {
  for (std::size_t i = 0; i < spectrum.n.size(); ++i) {
    spectrum.n[i] /= kCoatIor;
    spectrum.k[i] /= kCoatIor;
  }
  return spectrum;
}

// The clear coat's base lobe from the metal's reflectance seen through it, v, at cosine mu in air.
matc::Rgb layered(const matc::Rgb& v, double mu) {
  const double f = matc::coat_fresnel(mu, kCoatIor);
  matc::Rgb out{};
  for (std::size_t c = 0; c < 3; ++c)
    out[c] = matc::coated_base_reflectance(f, v[c]);
  return out;
}

double largest(const matc::Rgb& a, const matc::Rgb& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

Errors band_errors(double index, const std::array<double, 2>& band) {
  Errors worst{};
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    if (!preset.caveat.empty()) continue;
    const matc::Spectrum& metal = matc::preset_spectrum(preset);
    const matc::Spectrum relative = relative_to_coat(metal);
    const matc::UnderCoatCurve bare_under(std::make_unique<matc::SpectralCurve>(relative),
                                          kCoatIor);
    for (double thickness = band[0]; thickness <= band[1]; thickness += 25.0) {
      const matc::ThinFilm film{index, thickness};
      const matc::ThinFilmCurve in_air(metal, film);
      const matc::UnderCoatCurve under(
          std::make_unique<matc::ThinFilmCurve>(relative, matc::film_under_coat(film, kCoatIor)),
          kCoatIor);
      matc::runtime::FilmTable table;
      for (std::size_t i = 0; i < matc::runtime::FilmTable::kCosineNodes; ++i) {
        const double mu = matc::runtime::film_table_cosine(i);
        table.fresnel[i] = layered(under.at(mu), mu);
      }
      for (int j = 0; j <= 95; ++j) {
        const double mu = 0.05 + 0.01 * j;
        const matc::Rgb exact = layered(under.at(mu), mu);
        const matc::Rgb air = in_air.at(mu);
        const double transmitted = 1.0 - matc::coat_fresnel(mu, kCoatIor);
        const Errors errors = {
            largest(matc::runtime::film_fresnel(table, mu), exact),
            largest({air[0] * transmitted, air[1] * transmitted, air[2] * transmitted}, exact),
            largest(layered(in_air.at(matc::refracted_cosine(mu, kCoatIor)), mu), exact),
            largest(layered(bare_under.at(mu), mu), exact)};
        for (std::size_t k = 0; k < kColumns; ++k)
          worst[k] = std::max(worst[k], errors[k]);
      }
    }
  }
  return worst;
}

}  // namespace

int main() {
  std::vector<std::future<Errors>> rows;
  for (const double index : kIndices)
    for (const auto& band : kBands)
      rows.push_back(std::async(std::launch::async, band_errors, index, band));
  fmt::print(
      "| film index | thickness | ours: the table of the layered base | the film in air, times 1 - "
      "F_coat (glTF's clear coat) | the film in air, refracted into the coat | the coated metal "
      "without its film |\n|---:|---|---:|---:|---:|---:|\n");
  std::size_t next = 0;
  for (const double index : kIndices) {
    for (const auto& band : kBands) {
      fmt::print("| {:.2f} | {:.0f}-{:.0f} nm |", index, band[0], band[1]);
      for (const double error : rows[next++].get())
        fmt::print(" {:.4f} |", error);
      fmt::print("\n");
    }
  }
  return 0;
}
