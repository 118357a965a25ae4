// What a thin film over a metal does to the curves matc fits (issue #67, docs/accuracy.md "Thin
// films over metals"): for films of several thicknesses and indices over measured metals
// (titanium, gold, copper, iron, chromium), the exact spectral curve (optics/thin_film.h, reduced
// to RGB as bare metals are) against
//   - the default basis' fit of it (the 4-term decomposition carrying the film as one curve), and
//   - the same Airy sum over a dielectric base of the metal's F0 at each wavelength, the physics
//     of the engines' KHR_materials_iridescence (a base of index (1 + sqrt F0) / (1 - sqrt F0):
//     the metal's extinction, and its phase on reflection, dropped),
// each cell the worst over the metals, channels and cosines in [0.05, 1] (the range), and
// at normal incidence.
//   build/bench/matc_thin_film_study   (about 30 s on 2 cores; bench/accuracy/update-docs.sh)
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "fit/accuracy.h"
#include "fit/coefficients.h"
#include "optics/presets.h"
#include "optics/spectral.h"
#include "optics/thin_film.h"

namespace {

constexpr std::array<std::string_view, 5> kMetals = {"Ti", "Au", "Cu", "Fe", "Cr"};

// The dielectric that reflects as the metal does at normal incidence, per wavelength of the
// integration grid: the base the engines put under their film.
matc::Spectrum dielectric_base(const matc::Spectrum& metal) {
  matc::Spectrum base;
  for (int nm = matc::kCieFirstNm; nm <= matc::kCieLastNm; ++nm) {
    const double s = std::sqrt(
        std::min(matc::fresnel_normal_incidence(metal.at(static_cast<double>(nm))), 0.999999));
    base.wavelength_nm.push_back(nm);
    base.n.push_back((1.0 + s) / (1.0 - s));
    base.k.push_back(0.0);
  }
  return base;
}

struct Row {
  double fit = 0.0;        // the default basis' fit of the exact curve, worst over [0, 1]
  double engines = 0.0;    // the dielectric base against the exact curve, cos in [0.05, 1]
  double engines_0 = 0.0;  // the same at normal incidence
};

Row measure(const matc::ThinFilm& film) {
  Row row;
  for (const std::string_view symbol : kMetals) {
    const matc::Spectrum& metal = matc::preset_spectrum(*matc::find_metal_preset(symbol));
    const matc::ThinFilmCurve exact(metal, film);
    const matc::ErrorStats fit =
        matc::measure_accuracy(exact,
                               matc::solve_coefficients(exact, matc::runtime::shipped_basis()),
                               matc::runtime::shipped_shader_basis())
            .decomposition;
    row.fit = std::max({row.fit, fit.max_abs[0], fit.max_abs[1], fit.max_abs[2]});
    const matc::ThinFilmCurve engines(dielectric_base(metal), film);
    for (int j = 0; j <= 95; ++j) {
      const double mu = 0.05 + 0.01 * j;
      const matc::Rgb a = exact.at(mu), b = engines.at(mu);
      for (std::size_t c = 0; c < 3; ++c) {
        row.engines = std::max(row.engines, std::abs(a[c] - b[c]));
        if (j == 95) row.engines_0 = std::max(row.engines_0, std::abs(a[c] - b[c]));
      }
    }
  }
  return row;
}

}  // namespace

int main() {
  const std::vector<double> thicknesses = {0, 30, 50, 100, 200, 350, 500, 800};
  const std::vector<double> indices = {1.33, 1.5, 2.3};
  std::vector<std::future<Row>> rows;
  for (const double index : indices)
    for (const double thickness : thicknesses)
      rows.push_back(std::async(std::launch::async, measure, matc::ThinFilm{index, thickness}));
  fmt::print(
      "| film: index, thickness | the default basis' fit (4 terms) | the engines' dielectric base, "
      "cos 0.05-1 | the same at normal incidence |\n|---|---:|---:|---:|\n");
  std::size_t next = 0;
  for (const double index : indices) {
    for (const double thickness : thicknesses) {
      const Row row = rows[next++].get();
      fmt::print("| {:.2f}, {:.0f} nm | {:.4f} | {:.4f} | {:.4f} |\n", index, thickness, row.fit,
                 row.engines, row.engines_0);
    }
  }
  return 0;
}
