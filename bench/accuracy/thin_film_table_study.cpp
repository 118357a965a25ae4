// How finely must a shader's table sample a filmed metal's curve (issue #67, docs/accuracy.md "A
// film's curve as a table")? The 4-term basis cannot carry thick films (matc_thin_film_study); a
// table of F over the cosine, read with linear interpolation, can, at a size to be measured. For
// the 23 reliable measured metals under films of index 1.2-2.5 and 0-1000 nm (the issue's
// targets), each cell is the worst |table - exact| over metals, channels and cosines in
// [0.05, 1], for
//   - a fixed thickness: N nodes over the cosine, uniform in mu or in u = sqrt(mu) (denser
//     towards grazing, where the curve turns to 1), and
//   - a thickness texture: the same nodes over the cosine, and nodes every `step` nm over the
//     thickness, read bilinearly (the error of the thickness axis, at the midpoints between its
//     nodes, where linear interpolation errs most), over 0-1000 nm and over glTF's default
//     range, 100-400 nm.
// A table's error bounds the image light's too: the split sum of a piecewise-linear curve is a
// weighted average of its nodes (weights of the lobe, summing to at most 1), so Fbar from the
// table is within the table's error of Fbar from the exact curve.
//   build/bench/matc_thin_film_table_study   (about two minutes on 2 cores;
//   bench/accuracy/update-docs.sh)
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "optics/presets.h"
#include "optics/spectral.h"
#include "optics/thin_film.h"

namespace {

// The cosines every table is checked at: [0.05, 1] every 0.0025.
constexpr int kCheckedCosines = 381;
double checked_cosine(int j) {
  return 0.05 + 0.95 * j / (kCheckedCosines - 1);
}

enum class Spacing { mu, sqrt_mu };

double node_cosine(Spacing spacing, int i, int nodes) {
  const double t = static_cast<double>(i) / (nodes - 1);
  return spacing == Spacing::mu ? t : t * t;
}

// The piecewise-linear table of `curve` with `nodes` nodes, evaluated at mu.
struct CosineTable {
  Spacing spacing;
  std::vector<matc::Rgb> values;

  CosineTable(const matc::ReflectanceCurve& curve, Spacing s, int nodes) : spacing(s) {
    for (int i = 0; i < nodes; ++i)
      values.push_back(curve.at(node_cosine(spacing, i, nodes)));
  }
  matc::Rgb at(double mu) const {
    const double t = spacing == Spacing::mu ? mu : std::sqrt(mu);
    const double x = t * static_cast<double>(values.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(x), values.size() - 2);
    const double w = x - static_cast<double>(i);
    matc::Rgb out{};
    for (std::size_t c = 0; c < 3; ++c)
      out[c] = (1.0 - w) * values[i][c] + w * values[i + 1][c];
    return out;
  }
};

struct Layout {
  Spacing spacing;
  int nodes;
  std::string_view name;
};
constexpr std::array<Layout, 5> kLayouts = {{{Spacing::mu, 16, "16 in mu"},
                                             {Spacing::sqrt_mu, 16, "16 in sqrt(mu)"},
                                             {Spacing::mu, 32, "32 in mu"},
                                             {Spacing::sqrt_mu, 32, "32 in sqrt(mu)"},
                                             {Spacing::sqrt_mu, 64, "64 in sqrt(mu)"}}};

constexpr std::array<double, 4> kIndices = {1.2, 1.5, 2.0, 2.5};
// Thickness bands: every 25 nm from 0 to 1000 falls in one.
constexpr std::array<std::array<double, 2>, 4> kBands = {
    {{0.0, 100.0}, {125.0, 300.0}, {325.0, 600.0}, {625.0, 1000.0}}};
constexpr std::array<double, 4> kThicknessSteps = {20.0, 10.0, 5.0, 2.5};

std::vector<const matc::Spectrum*> measured_metals() {
  std::vector<const matc::Spectrum*> metals;
  for (const matc::MetalPreset& preset : matc::metal_presets())
    if (preset.caveat.empty()) metals.push_back(&matc::preset_spectrum(preset));
  return metals;
}

// Worst error of each cosine layout over the metals, for films of `index` in a thickness band.
std::array<double, kLayouts.size()> fixed_thickness_errors(double index,
                                                           const std::array<double, 2>& band) {
  std::array<double, kLayouts.size()> worst{};
  for (const matc::Spectrum* metal : measured_metals()) {
    for (double thickness = band[0]; thickness <= band[1]; thickness += 25.0) {
      const matc::ThinFilmCurve exact(*metal, {index, thickness});
      std::vector<matc::Rgb> reference(kCheckedCosines);
      for (int j = 0; j < kCheckedCosines; ++j)
        reference[static_cast<std::size_t>(j)] = exact.at(checked_cosine(j));
      for (std::size_t l = 0; l < kLayouts.size(); ++l) {
        const CosineTable table(exact, kLayouts[l].spacing, kLayouts[l].nodes);
        for (int j = 0; j < kCheckedCosines; ++j) {
          const matc::Rgb a = table.at(checked_cosine(j));
          for (std::size_t c = 0; c < 3; ++c)
            worst[l] =
                std::max(worst[l], std::abs(a[c] - reference[static_cast<std::size_t>(j)][c]));
        }
      }
    }
  }
  return worst;
}

// Worst error of linear interpolation over the thickness, every `step` nm from 0 to 1000, at the
// midpoints between nodes and 20 cosines in [0.05, 1], over the metals, for films of `index`.
// Every node and midpoint is a multiple of 1.25 nm: each film is evaluated once.
// The first element of each triple is over all 20 cosines, the second over cosines of 0.2 and up
// (away from grazing, where the film's two interfaces both reflect strongly and its resonances
// turn sharp), the third over all cosines between nodes within glTF's default range, 100-400 nm
// (what a thickness stack over that range reads: compile/film_tables.h).
using ThicknessErrors = std::array<std::array<double, 3>, kThicknessSteps.size()>;
ThicknessErrors thickness_axis_errors(double index) {
  constexpr double kGrain = 1.25;
  constexpr int kGrains = 800;  // 1000 nm
  ThicknessErrors worst{};
  for (const matc::Spectrum* metal : measured_metals()) {
    std::vector<std::array<matc::Rgb, 20>> values(kGrains + 1);
    for (int g = 0; g <= kGrains; ++g) {
      const matc::ThinFilmCurve film(*metal, {index, kGrain * g});
      for (std::size_t j = 0; j < 20; ++j)
        values[static_cast<std::size_t>(g)][j] = film.at(0.05 + 0.05 * static_cast<double>(j));
    }
    for (std::size_t s = 0; s < kThicknessSteps.size(); ++s) {
      const auto stride = static_cast<std::size_t>(kThicknessSteps[s] / kGrain);
      for (std::size_t lower = 0; lower + stride <= kGrains; lower += stride) {
        const auto& a = values[lower];
        const auto& b = values[lower + stride / 2];
        const auto& c = values[lower + stride];
        for (std::size_t j = 0; j < 20; ++j) {
          for (std::size_t channel = 0; channel < 3; ++channel) {
            const double error = std::abs(0.5 * (a[j][channel] + c[j][channel]) - b[j][channel]);
            worst[s][0] = std::max(worst[s][0], error);
            if (j >= 3) worst[s][1] = std::max(worst[s][1], error);
            const double from_nm = kGrain * static_cast<double>(lower);
            if (from_nm >= 100.0 && from_nm + kThicknessSteps[s] <= 400.0)
              worst[s][2] = std::max(worst[s][2], error);
          }
        }
      }
    }
  }
  return worst;
}

}  // namespace

int main() {
  std::vector<std::future<std::array<double, kLayouts.size()>>> fixed;
  for (const double index : kIndices)
    for (const auto& band : kBands)
      fixed.push_back(std::async(std::launch::async, fixed_thickness_errors, index, band));
  std::vector<std::future<ThicknessErrors>> textured;
  for (const double index : kIndices)
    textured.push_back(std::async(std::launch::async, thickness_axis_errors, index));

  fmt::print("| film index | thickness |");
  for (const Layout& layout : kLayouts)
    fmt::print(" {} nodes |", layout.name);
  fmt::print("\n|---:|---|");
  for (std::size_t l = 0; l < kLayouts.size(); ++l)
    fmt::print("---:|");
  fmt::print("\n");
  std::size_t next = 0;
  for (const double index : kIndices) {
    for (const auto& band : kBands) {
      fmt::print("| {:.1f} | {:.0f}-{:.0f} nm |", index, band[0], band[1]);
      for (const double error : fixed[next].get())
        fmt::print(" {:.4f} |", error);
      ++next;
      fmt::print("\n");
    }
  }
  fmt::print(
      "\nA thickness texture, 0-1000 nm: linear interpolation over the thickness, worst at the "
      "midpoints between nodes, over cos 0.05-1 / cos 0.2-1:\n\n| film index |");
  const auto header = [](double span) {
    for (const double step : kThicknessSteps)
      fmt::print(" every {:g} nm ({} nodes) |", step, static_cast<int>(span / step) + 1);
    fmt::print("\n|---:|");
    for (std::size_t s = 0; s < kThicknessSteps.size(); ++s)
      fmt::print("---:|");
    fmt::print("\n");
  };
  header(1000.0);
  std::vector<ThicknessErrors> errors;
  for (auto& future : textured)
    errors.push_back(future.get());
  for (std::size_t i = 0; i < kIndices.size(); ++i) {
    fmt::print("| {:.1f} |", kIndices[i]);
    for (const auto& [all, away_from_grazing, gltf_range] : errors[i])
      fmt::print(" {:.4f} / {:.4f} |", all, away_from_grazing);
    fmt::print("\n");
  }
  fmt::print(
      "\nThe same over glTF's default range, 100-400 nm (what a thickness stack over it reads), "
      "cos 0.05-1:\n\n| film index |");
  header(300.0);
  for (std::size_t i = 0; i < kIndices.size(); ++i) {
    fmt::print("| {:.1f} |", kIndices[i]);
    for (const auto& triple : errors[i])
      fmt::print(" {:.4f} |", triple[2]);
    fmt::print("\n");
  }
  return 0;
}
