// Prints the accuracy tables of docs/accuracy.md: the decomposition, Schlick and F82-tint against
// the exact Fresnel curve of every measured metal, and over a grid of artistic (r, g) inputs.
// Run through bench/accuracy/update-docs.sh; tests/scripts/check_docs_block.sh keeps the docs in
// sync.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/core.h>

#include "default_basis.h"
#include "error_totals.h"
#include "f82_tint_look.h"
#include "fit/accuracy.h"
#include "fit/coefficients.h"
#include "lut/comparison_lobes.h"
#include "lut/preintegrate.h"
#include "lut/split_sum_reference.h"
#include "optics/gamut.h"
#include "optics/gulbrandsen.h"
#include "optics/presets.h"
#include "optics/spectral.h"
#include "random_artistic.h"

namespace {

using matc::ErrorStats;
using matc::FitAccuracy;

using matc::bench::Totals;

using matc::runtime::BasisKind;

FitAccuracy measure(const matc::ReflectanceCurve& curve,
                    BasisKind kind = matc::runtime::kDefaultBasis) {
  return matc::measure_accuracy(curve,
                                matc::solve_coefficients(curve, matc::runtime::shipped_basis(kind)),
                                matc::runtime::shipped_shader_basis(kind));
}

// The per-metal table (unless summary_only) and the summary over the reliable metals.
void print_metals(bool summary_only) {
  if (!summary_only) {
    fmt::print(
        "| metal | F0 (linear sRGB) | ours max | ours RMS | extended basis max | paper basis max | "
        "f82 basis max | Schlick max | F82-tint max |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  }
  Totals ours;
  Totals extended;
  Totals paper;
  Totals f82_basis;
  Totals schlick;
  Totals f82;
  // What a default build gives a measured metal (a basis per material).
  const BasisKind default_basis = matc::bench::default_basis_for(matc::SpectralInput{});
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    const matc::SpectralCurve curve(matc::preset_spectrum(preset));
    const FitAccuracy accuracy = measure(curve, default_basis);
    const FitAccuracy extended_accuracy = measure(curve, BasisKind::extended);
    const FitAccuracy paper_accuracy = measure(curve, BasisKind::paper);
    const FitAccuracy f82_basis_accuracy = measure(curve, BasisKind::f82);
    const matc::Rgb f0 = curve.at(1.0);
    const bool counted = preset.caveat.empty();
    if (!summary_only) {
      fmt::print(
          "| {} {}{} | {:.3f}, {:.3f}, {:.3f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | "
          "{:.4f} | {:.4f} |\n",
          preset.symbol, preset.name, counted ? "" : " (unreliable, not counted)", f0[0], f0[1],
          f0[2], matc::worst_channel(accuracy.decomposition.max_abs),
          matc::worst_channel(accuracy.decomposition.rms),
          matc::worst_channel(extended_accuracy.decomposition.max_abs),
          matc::worst_channel(paper_accuracy.decomposition.max_abs),
          matc::worst_channel(f82_basis_accuracy.decomposition.max_abs),
          matc::worst_channel(accuracy.schlick.max_abs),
          matc::worst_channel(accuracy.f82_tint.max_abs));
    }
    if (counted) {
      ours.add(accuracy.decomposition);
      extended.add(extended_accuracy.decomposition);
      paper.add(paper_accuracy.decomposition);
      f82_basis.add(f82_basis_accuracy.decomposition);
      schlick.add(accuracy.schlick);
      f82.add(accuracy.f82_tint);
    }
  }
  fmt::print("{}Over the {} curves of {} measured metals (RGB each), exact Fresnel vs:\n\n",
             summary_only ? "" : "\n", ours.curves, ours.curves / 3);
  fmt::print(
      "| model | worst-channel max error | mean of per-curve max |\n"
      "|---|---:|---:|\n");
  fmt::print("| ours (default options: `{}` for measured metals) | {:.4f} | {:.4f} |\n",
             matc::runtime::basis_name(default_basis), ours.worst, ours.mean());
  fmt::print("| ours with `--basis extended` | {:.4f} | {:.4f} |\n", extended.worst,
             extended.mean());
  fmt::print("| ours with `--basis paper` | {:.4f} | {:.4f} |\n", paper.worst, paper.mean());
  fmt::print("| ours with `--basis f82` | {:.4f} | {:.4f} |\n", f82_basis.worst, f82_basis.mean());
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

// 500 random grey artistic inputs (the study's draws): worst and mean max error per model.
void print_random_artistic() {
  fmt::print(
      "\n| 500 random artistic inputs | ours | ours with `--basis extended` | ours with `--basis "
      "paper` | ours with `--basis f82` | Schlick | F82-tint "
      "|\n|---|---:|---:|---:|---:|---:|---:|\n");
  for (const double r_max : {0.8, 1.0}) {
    Totals ours;
    Totals extended;
    Totals paper;
    Totals f82_basis;
    Totals schlick;
    Totals f82;
    for (const auto& [r, g] : matc::bench::random_artistic_inputs(500, r_max)) {
      const matc::ComplexIor ior = matc::gulbrandsen_to_ior({r, g});
      const matc::IorCurve curve({ior, ior, ior});
      const FitAccuracy accuracy = measure(curve);
      const FitAccuracy paper_accuracy = measure(curve, BasisKind::paper);
      // Grey: one channel stands for all three.
      ours.add_one(accuracy.decomposition.max_abs[0]);
      extended.add_one(measure(curve, BasisKind::extended).decomposition.max_abs[0]);
      paper.add_one(paper_accuracy.decomposition.max_abs[0]);
      f82_basis.add_one(measure(curve, BasisKind::f82).decomposition.max_abs[0]);
      schlick.add_one(accuracy.schlick.max_abs[0]);
      f82.add_one(accuracy.f82_tint.max_abs[0]);
    }
    fmt::print(
        "| r <= {:.1f}: worst / mean | {:.4f} / {:.4f} | {:.4f} / {:.4f} | {:.4f} / {:.4f} | "
        "{:.4f} / {:.4f} | {:.4f} / {:.4f} | {:.4f} / {:.4f} |\n",
        r_max, ours.worst, ours.mean(), extended.worst, extended.mean(), paper.worst, paper.mean(),
        f82_basis.worst, f82_basis.mean(), schlick.worst, schlick.mean(), f82.worst, f82.mean());
  }
}

// How well a bilinearly filtered table reproduces the integral it samples: the worst difference
// over bbar_0..bbar_3 between the filtered value and a direct 4096-sample integral, at 400 points
// that crowd towards grazing. `to_u` maps NdotV to the table's horizontal axis.
double reconstruction_error(std::size_t size, const std::function<double(double)>& to_u,
                            const std::function<double(double)>& from_u) {
  const auto basis = matc::runtime::shipped_basis();
  const double last = static_cast<double>(size - 1);
  std::vector<std::array<double, 4>> table(size * size);
  for (std::size_t y = 0; y < size; ++y) {
    for (std::size_t x = 0; x < size; ++x) {
      table[y * size + x] = matc::preintegrate_basis(basis, from_u(static_cast<double>(x) / last),
                                                     static_cast<double>(y) / last, 1024);
    }
  }
  double worst = 0.0;
  for (int i = 0; i < 400; ++i) {
    const double mu = std::pow((i % 20 + 0.37) / 20.0, 3.0);
    const double roughness = (i / 20 + 0.61) / 20.0;
    const double px = to_u(mu) * last;
    const double py = roughness * last;
    const std::size_t x = std::min(static_cast<std::size_t>(px), size - 2);
    const std::size_t y = std::min(static_cast<std::size_t>(py), size - 2);
    const double tx = px - static_cast<double>(x);
    const double ty = py - static_cast<double>(y);
    const auto direct = matc::preintegrate_basis(basis, mu, roughness, 4096);
    for (std::size_t c = 0; c < 4; ++c) {
      const auto at = [&](std::size_t xx, std::size_t yy) { return table[yy * size + xx][c]; };
      const double filtered = (1 - ty) * ((1 - tx) * at(x, y) + tx * at(x + 1, y)) +
                              ty * ((1 - tx) * at(x, y + 1) + tx * at(x + 1, y + 1));
      worst = std::max(worst, std::abs(filtered - direct[c]));
    }
  }
  return worst;
}

// Sampling error of the default 1024 samples per texel: the worst difference from a 65536-sample
// integral over bbar_0..bbar_3 on a 9 x 9 grid (NdotV = (i/8)^2, roughness = j/8).
void print_convergence() {
  const auto basis = matc::runtime::shipped_basis();
  double worst = 0.0;
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      const auto coarse = matc::preintegrate_basis(basis, std::pow(i / 8.0, 2), j / 8.0, 1024);
      const auto fine = matc::preintegrate_basis(basis, std::pow(i / 8.0, 2), j / 8.0, 65536);
      for (std::size_t c = 0; c < 4; ++c)
        worst = std::max(worst, std::abs(coarse[c] - fine[c]));
    }
  }
  fmt::print("Sampling error at 1024 samples per texel (vs 65536): {:.4f}\n\n", worst);
}

void print_reconstruction() {
  fmt::print(
      "| table size | u = NdotV (linear) | u = sqrt(NdotV) (shipped) |\n"
      "|---:|---:|---:|\n");
  const auto identity = [](double x) { return x; };
  const auto square_root = [](double x) { return std::sqrt(x); };
  const auto square = [](double x) { return x * x; };
  for (const std::size_t size : {32, 64, 128}) {
    fmt::print("| {}x{} | {:.4f} | {:.4f} |\n", size, size,
               reconstruction_error(size, identity, identity),
               reconstruction_error(size, square_root, square));
  }
}

// Per-metal rows (unless summary_only), then the worst and mean rows.
void print_preintegrated(bool summary_only) {
  const auto basis = matc::runtime::shipped_basis();
  const matc::Lut ours = matc::preintegrate_lut(basis, {});
  const auto paper_basis = matc::runtime::shipped_basis(BasisKind::paper);
  const matc::Lut paper = matc::preintegrate_lut(paper_basis, {});
  const matc::ComparisonLobes lobes(basis.samples());
  const matc::Lut lobe_lut = matc::preintegrate_lut(lobes.view(), {});
  constexpr std::array<double, 9> kNdotV = {0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 1.0};
  std::vector<matc::SplitSumEstimator> estimators;
  std::vector<std::pair<double, double>> points;
  for (const double ndotv : kNdotV) {
    for (int j = 0; j < 10; ++j) {
      const double roughness = (j + 0.5) / 10.0;
      estimators.emplace_back(ndotv, roughness, 16384);
      points.emplace_back(ndotv, roughness);
    }
  }
  fmt::print(
      "{}| metal | ours (4 terms) | ours with `--basis paper` | Schlick split sum (2 terms) | "
      "F82-tint split sum (3 terms) |\n|---|---:|---:|---:|---:|\n",
      summary_only ? "\nPreintegrated for image-based lighting (128x128 table, one fetch), "
                     "against the exact split-sum integral:\n\n"
                   : "");
  Totals totals[4];
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    if (!preset.caveat.empty()) continue;
    const matc::TabulatedCurve curve(matc::SpectralCurve(matc::preset_spectrum(preset)));
    const auto c = matc::solve_coefficients(curve, basis);
    const auto c_paper = matc::solve_coefficients(curve, paper_basis);
    const matc::Rgb f0 = curve.at(1.0);
    const matc::Rgb f82 = curve.at(matc::kF82MuBar);
    ErrorStats errors[4];
    for (std::size_t p = 0; p < points.size(); ++p) {
      const auto [ndotv, roughness] = points[p];
      const matc::Rgb reference = estimators[p].integrate(curve);
      const matc::Rgb decomposed = matc::runtime::evaluate_fbar(c, ours.view(), ndotv, roughness);
      const matc::Rgb decomposed_paper =
          matc::runtime::evaluate_fbar(c_paper, paper.view(), ndotv, roughness);
      const auto lobe = matc::runtime::sample_lut(lobe_lut.view(), ndotv, roughness);
      for (std::size_t ch = 0; ch < 3; ++ch) {
        const double mu_bar = matc::kF82MuBar;
        const double a = (matc::fresnel_schlick(mu_bar, f0[ch]) - f82[ch]) /
                         (mu_bar * std::pow(1.0 - mu_bar, 6.0));
        const double schlick = f0[ch] * lobe[0] + (1.0 - f0[ch]) * lobe[1];
        const double values[4] = {decomposed[ch], decomposed_paper[ch], schlick,
                                  schlick - a * lobe[2]};
        for (std::size_t m = 0; m < 4; ++m) {
          errors[m].max_abs[ch] =
              std::max(errors[m].max_abs[ch], std::abs(values[m] - reference[ch]));
        }
      }
    }
    if (!summary_only) {
      fmt::print("| {} {} | {:.4f} | {:.4f} | {:.4f} | {:.4f} |\n", preset.symbol, preset.name,
                 matc::worst_channel(errors[0].max_abs), matc::worst_channel(errors[1].max_abs),
                 matc::worst_channel(errors[2].max_abs), matc::worst_channel(errors[3].max_abs));
    }
    for (std::size_t m = 0; m < 4; ++m)
      totals[m].add(errors[m]);
  }
  fmt::print(
      "| **worst channel, all metals** | **{:.4f}** | **{:.4f}** | **{:.4f}** | **{:.4f}** |\n",
      totals[0].worst, totals[1].worst, totals[2].worst, totals[3].worst);
  fmt::print("| mean of per-curve max | {:.4f} | {:.4f} | {:.4f} | {:.4f} |\n", totals[0].mean(),
             totals[1].mean(), totals[2].mean(), totals[3].mean());
}

}  // namespace

// Four decimals, or two significant digits below 1e-4 (where "0.0000" would claim exactness).
std::string format_error(double error) {
  return error >= 1e-4 ? fmt::format("{:.4f}", error) : fmt::format("{:.1e}", error);
}

// No arguments: the curve tables of docs/accuracy.md. --summary: the summaries the README quotes.
// --lut: the preintegrated tables (table reconstruction, then Fbar against a direct reference).
// The F82-tint material model (OpenPBR's metal): our fit against the F82-tint curve it stands
// for, over a grid of (F0, tint), and for the F82-tint parameters of the measured metals.
void print_f82_tint() {
  constexpr std::array<double, 7> kTints = {0.0, 0.5, 0.7, 0.8, 0.9, 0.95, 1.0};
  // What a default build gives an F82-tint material (a basis per material).
  const BasisKind default_basis = matc::bench::default_basis_for(matc::F82TintInput{});
  for (const BasisKind kind : {BasisKind::powers, default_basis}) {
    if (kind == BasisKind::powers) {
      fmt::print("With `--basis powers` (one basis forced on every material):\n\n| F0 \\ tint |");
    } else {
      fmt::print("\nAt default options (a basis per material: each takes `{}`):\n\n| F0 \\ tint |",
                 matc::runtime::basis_name(kind));
    }
    for (const double tint : kTints)
      fmt::print(" {:.2f} |", tint);
    fmt::print("\n|---:|");
    for (std::size_t i = 0; i < kTints.size(); ++i)
      fmt::print("---:|");
    fmt::print("\n");
    for (const double f0 : {0.02, 0.2, 0.4, 0.6, 0.8, 0.9, 0.95}) {
      fmt::print("| {:.2f} |", f0);
      for (const double tint : kTints) {
        const FitAccuracy accuracy =
            measure(matc::F82TintCurve({f0, f0, f0}, {tint, tint, tint}), kind);
        fmt::print(" {} |", format_error(accuracy.decomposition.max_abs[0]));
      }
      fmt::print("\n");
    }
  }
  // Each measured metal as an F82-tint material: F0 and F(1/7) of its exact curve, so tint =
  // F(1/7) / Schlick(1/7) per channel (what an OpenPBR look matched to the metal would use).
  Totals ours;
  Totals powers;
  Totals schlick;
  double tint_min = 1.0;
  double tint_max = 0.0;
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    if (!preset.caveat.empty()) continue;
    const matc::SpectralCurve exact(matc::preset_spectrum(preset));
    const auto [f0, tint] = matc::bench::f82_tint_look(exact);
    for (const double value : tint) {
      tint_min = std::min(tint_min, value);
      tint_max = std::max(tint_max, value);
    }
    const FitAccuracy accuracy = measure(matc::F82TintCurve(f0, tint), default_basis);
    ours.add(accuracy.decomposition);
    powers.add(measure(matc::F82TintCurve(f0, tint), BasisKind::powers).decomposition);
    schlick.add(accuracy.schlick);
  }
  fmt::print(
      "\nThe {} reliable measured metals as F82-tint materials (tint = F(1/7) / Schlick(1/7) of "
      "the exact curve, {:.3f} to {:.3f}), against their F82-tint curves:\n\n"
      "| model | worst-channel max error | mean of per-curve max |\n|---|---:|---:|\n"
      "| ours (default options: `{}`) | {} | {} |\n| ours with `--basis powers` | {:.4f} | {:.4f} "
      "|\n"
      "| Schlick | {:.4f} | {:.4f} |\n",
      ours.curves / 3, tint_min, tint_max, matc::runtime::basis_name(default_basis),
      format_error(ours.worst), format_error(ours.mean()), powers.worst, powers.mean(),
      schlick.worst, schlick.mean());
}

// The measured metals in each working space: the same fits, and how far each space's curves
// leave [0, 1].
void print_color_spaces() {
  fmt::print(
      "| working space | ours worst | ours mean | Schlick worst | F82-tint worst | metals outside "
      "[0, 1] | furthest outside |\n|---|---:|---:|---:|---:|---:|---|\n");
  for (const auto& space : matc::color_spaces()) {
    Totals ours;
    Totals schlick;
    Totals f82;
    std::size_t outside = 0;
    double furthest = 0.0;
    std::string furthest_metal = "-";
    for (const matc::MetalPreset& preset : matc::metal_presets()) {
      if (!preset.caveat.empty()) continue;
      const matc::SpectralCurve curve(matc::preset_spectrum(preset), space.id);
      const FitAccuracy accuracy = measure(curve);
      ours.add(accuracy.decomposition);
      schlick.add(accuracy.schlick);
      f82.add(accuracy.f82_tint);
      const matc::CurveRange range = matc::measure_curve_range(curve);
      if (range.within_unit_range()) continue;
      ++outside;
      for (std::size_t c = 0; c < 3; ++c) {
        const double beyond = std::max(range.max[c] - 1.0, -range.min[c]);
        if (beyond > furthest) {
          furthest = beyond;
          furthest_metal = fmt::format("{} {} {:.4f}", preset.symbol, "RGB"[c],
                                       range.max[c] > 1.0 ? range.max[c] : range.min[c]);
        }
      }
    }
    fmt::print("| {} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {} | {} |\n", space.name, ours.worst,
               ours.mean(), schlick.worst, f82.worst, outside, furthest_metal);
  }
}

int main(int argc, char** argv) {
  const std::string_view mode = argc > 1 ? argv[1] : "";
  if (mode == "--f82-tint") {
    print_f82_tint();
    return 0;
  }
  if (mode == "--color-spaces") {
    print_color_spaces();
    return 0;
  }
  if (mode == "--lut") {
    print_convergence();
    print_reconstruction();
    fmt::print("\n");
    print_preintegrated(false);
    return 0;
  }
  const bool summary_only = mode == "--summary";
  print_metals(summary_only);
  if (summary_only) print_preintegrated(true);
  if (!summary_only) {
    print_artistic_grid();
    print_random_artistic();
  }
  return 0;
}
