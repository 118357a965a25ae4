// Prints the accuracy tables of docs/accuracy.md: the decomposition, Schlick and F82-tint against
// the exact Fresnel curve of every measured metal, and over a grid of artistic (r, g) inputs.
// Run through bench/accuracy/update-docs.sh; tests/check_docs_block.sh keeps the docs in sync.
#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/core.h>

#include "matc/fit/accuracy.h"
#include "matc/fit/coefficients.h"
#include "matc/optics/gulbrandsen.h"
#include "matc/optics/presets.h"
#include "matc/optics/spectral.h"

namespace {

using matc::ErrorStats;
using matc::FitAccuracy;

double worst(const matc::Rgb& values) {
  return *std::max_element(values.begin(), values.end());
}

struct Totals {
  double worst = 0.0;
  double sum_of_max = 0.0;
  std::size_t curves = 0;
  void add(const ErrorStats& stats) {
    for (const double value : stats.max_abs) {
      worst = std::max(worst, value);
      sum_of_max += value;
      ++curves;
    }
  }
  double mean() const { return sum_of_max / static_cast<double>(curves); }
};

FitAccuracy measure(const matc::ReflectanceCurve& curve) {
  const auto basis = matc::runtime::paper_basis();
  return matc::measure_accuracy(curve, matc::solve_coefficients(curve, basis), basis);
}

// The per-metal table (unless summary_only) and the summary over the reliable metals.
void print_metals(bool summary_only) {
  if (!summary_only) {
    fmt::print(
        "| metal | F0 (linear sRGB) | ours max | ours RMS | Schlick max | F82-tint max |\n"
        "|---|---|---:|---:|---:|---:|\n");
  }
  Totals ours;
  Totals schlick;
  Totals f82;
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    const matc::SpectralCurve curve(matc::preset_spectrum(preset));
    const FitAccuracy accuracy = measure(curve);
    const matc::Rgb f0 = curve.at(1.0);
    const bool counted = preset.caveat.empty();
    if (!summary_only) {
      fmt::print("| {} {}{} | {:.3f}, {:.3f}, {:.3f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} |\n",
                 preset.symbol, preset.name, counted ? "" : " (unreliable, not counted)", f0[0],
                 f0[1], f0[2], worst(accuracy.decomposition.max_abs),
                 worst(accuracy.decomposition.rms), worst(accuracy.schlick.max_abs),
                 worst(accuracy.f82_tint.max_abs));
    }
    if (counted) {
      ours.add(accuracy.decomposition);
      schlick.add(accuracy.schlick);
      f82.add(accuracy.f82_tint);
    }
  }
  fmt::print("{}Over the {} curves of {} measured metals (RGB each), exact Fresnel vs:\n\n",
             summary_only ? "" : "\n", ours.curves, ours.curves / 3);
  fmt::print(
      "| model | worst-channel max error | mean of per-curve max |\n"
      "|---|---:|---:|\n");
  fmt::print("| ours (paper basis) | {:.4f} | {:.4f} |\n", ours.worst, ours.mean());
  fmt::print("| Schlick | {:.4f} | {:.4f} |\n", schlick.worst, schlick.mean());
  fmt::print("| F82-tint | {:.4f} | {:.4f} |\n", f82.worst, f82.mean());
}

// Artistic inputs (grey): our max error over an (r, g) grid, and Schlick's and F82-tint's worst
// over the same row.
void print_artistic_grid() {
  constexpr std::array<double, 7> kEdgeTints = {0.0, 0.2, 0.4, 0.6, 0.8, 0.9, 1.0};
  fmt::print("\n| r \\ g |");
  for (const double g : kEdgeTints)
    fmt::print(" {:.1f} |", g);
  fmt::print(" Schlick, worst g | F82-tint, worst g |\n|---:|");
  for (std::size_t i = 0; i < kEdgeTints.size() + 2; ++i)
    fmt::print("---:|");
  fmt::print("\n");
  for (const double r : {0.05, 0.2, 0.4, 0.6, 0.8, 0.9, 0.95, 0.99}) {
    double schlick = 0.0;
    double f82 = 0.0;
    fmt::print("| {:.2f} |", r);
    for (const double g : kEdgeTints) {
      const matc::ComplexIor ior = matc::gulbrandsen_to_ior({r, g});
      const FitAccuracy accuracy = measure(matc::IorCurve({ior, ior, ior}));
      fmt::print(" {:.4f} |", accuracy.decomposition.max_abs[0]);
      schlick = std::max(schlick, accuracy.schlick.max_abs[0]);
      f82 = std::max(f82, accuracy.f82_tint.max_abs[0]);
    }
    fmt::print(" {:.4f} | {:.4f} |\n", schlick, f82);
  }
}

}  // namespace

// No arguments: every table of docs/accuracy.md. --summary: the summary the README quotes.
int main(int argc, char** argv) {
  const bool summary_only = argc > 1 && std::string_view(argv[1]) == "--summary";
  print_metals(summary_only);
  if (!summary_only) print_artistic_grid();
  return 0;
}
