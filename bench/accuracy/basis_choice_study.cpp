// Which shipped basis each kind of material wants (issue #66, docs/accuracy.md "A basis per
// material"): every family of curves a build meets (measured metals, F82-tint looks, Schlick's
// curve as glTF's F0-only metals import, Gulbrandsen's (r, g), complex indices) fitted with each
// shipped basis; per family the worst and the mean of per-curve max error with each basis, with
// the best shipped basis chosen per curve, and with the rule `matc --basis auto` applies
// (compile/basis_choice.h: F82-tint and Schlick curves to `f82`, every exact curve (measured,
// (r, g), n and k) to `powers`), asked of a material of each family's model. Each cell:
// worst max error / mean of per-curve max errors, each channel a curve (as docs/accuracy.md
// counts them); "best per curve" picks one basis per material, the least worst channel, and
// says how many materials each basis won.
//   build/bench/matc_basis_choice_study
#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "default_basis.h"
#include "error_totals.h"
#include "f82_tint_look.h"
#include "fit/accuracy.h"
#include "fit/coefficients.h"
#include "optics/fresnel.h"
#include "optics/gulbrandsen.h"
#include "optics/presets.h"
#include "optics/reflectance_curve.h"
#include "optics/spectral.h"
#include "random_artistic.h"

namespace {

using matc::runtime::BasisKind;

constexpr std::array<BasisKind, 4> kBases = {BasisKind::powers, BasisKind::extended,
                                             BasisKind::paper, BasisKind::f82};

// A family of curves and the basis the rule gives them.
struct Family {
  std::string name;
  BasisKind rule;
  std::vector<std::unique_ptr<matc::ReflectanceCurve>> curves;
};

// Our error for `curve` fitted with `kind`, as the shaders evaluate it (per channel).
matc::ErrorStats fit_error(const matc::ReflectanceCurve& curve, BasisKind kind) {
  return matc::measure_accuracy(curve,
                                matc::solve_coefficients(curve, matc::runtime::shipped_basis(kind)),
                                matc::runtime::shipped_shader_basis(kind))
      .decomposition;
}

double worst_channel(const matc::ErrorStats& stats) {
  return std::max({stats.max_abs[0], stats.max_abs[1], stats.max_abs[2]});
}

std::vector<Family> families() {
  std::vector<Family> out;
  const BasisKind spectral_rule = matc::bench::default_basis_for(matc::SpectralInput{});
  const BasisKind f82_tint_rule = matc::bench::default_basis_for(matc::F82TintInput{});
  Family measured{"the 23 reliable measured metals (exact spectral curves)", spectral_rule, {}};
  Family measured_f82{
      "the same metals as F82-tint looks (their own F0 and F82)", f82_tint_rule, {}};
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    if (!preset.caveat.empty()) continue;
    auto exact = std::make_unique<matc::SpectralCurve>(matc::preset_spectrum(preset));
    const matc::bench::F82TintLook look = matc::bench::f82_tint_look(*exact);
    measured_f82.curves.push_back(std::make_unique<matc::F82TintCurve>(look.f0, look.tint));
    measured.curves.push_back(std::move(exact));
  }
  out.push_back(std::move(measured));
  out.push_back(std::move(measured_f82));

  Family grid{"F82-tint, grey grid: F0 0.02-0.98 (9), tint 0-1 (11)", f82_tint_rule, {}};
  for (const double f0 : {0.02, 0.1, 0.2, 0.35, 0.5, 0.65, 0.8, 0.9, 0.98}) {
    for (int t = 0; t <= 10; ++t) {
      const double tint = t / 10.0;
      grid.curves.push_back(
          std::make_unique<matc::F82TintCurve>(matc::Rgb{f0, f0, f0}, matc::Rgb{tint, tint, tint}));
    }
  }
  out.push_back(std::move(grid));

  Family random_f82{"F82-tint, 200 random coloured looks (F0 0.02-0.98, tint 0-1 per channel)",
                    f82_tint_rule,
                    {}};
  matc::bench::UnitDraws draws(6601);
  for (int i = 0; i < 200; ++i) {
    matc::Rgb f0{}, tint{};
    for (std::size_t c = 0; c < 3; ++c) {
      f0[c] = 0.02 + 0.96 * draws();
      tint[c] = draws();
    }
    random_f82.curves.push_back(std::make_unique<matc::F82TintCurve>(f0, tint));
  }
  out.push_back(std::move(random_f82));

  Family schlick{
      "Schlick's curve (tint 1: glTF's F0-only metals), F0 0.02-0.98 (49)", f82_tint_rule, {}};
  for (int i = 0; i < 49; ++i) {
    const double f0 = 0.02 + 0.96 * i / 48.0;
    schlick.curves.push_back(
        std::make_unique<matc::F82TintCurve>(matc::Rgb{f0, f0, f0}, matc::Rgb{1.0, 1.0, 1.0}));
  }
  out.push_back(std::move(schlick));

  Family artistic{"Gulbrandsen (r, g), 200 random (r < 0.99)",
                  matc::bench::default_basis_for(matc::ArtisticInput{}),
                  {}};
  for (const auto& [r, g] : matc::bench::random_artistic_inputs(200, 0.99)) {
    const matc::ComplexIor ior = matc::gulbrandsen_to_ior({r, g});
    artistic.curves.push_back(std::make_unique<matc::IorCurve>(std::array{ior, ior, ior}));
  }
  out.push_back(std::move(artistic));

  Family conductors{"complex indices, 200 random conductors (n 0.05-3, k 0.5-8)",
                    matc::bench::default_basis_for(matc::IorInput{}),
                    {}};
  matc::bench::UnitDraws index_draws(6602);
  for (int i = 0; i < 200; ++i) {
    const matc::ComplexIor ior{0.05 + 2.95 * index_draws(), 0.5 + 7.5 * index_draws()};
    conductors.curves.push_back(std::make_unique<matc::IorCurve>(std::array{ior, ior, ior}));
  }
  out.push_back(std::move(conductors));
  return out;
}

std::string cell(const matc::bench::Totals& totals) {
  const auto number = [](double value) {
    return value < 1e-4 ? fmt::format("{:.1e}", value) : fmt::format("{:.4f}", value);
  };
  return fmt::format("{} / {}", number(totals.worst), number(totals.mean()));
}

}  // namespace

int main() {
  fmt::print(
      "| curves | rule | `powers` | `extended` | `paper` | `f82` | best per curve | the rule |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const Family& family : families()) {
    std::array<matc::bench::Totals, kBases.size()> by_basis{};
    matc::bench::Totals best, rule;
    std::array<std::size_t, kBases.size()> chosen{};
    for (const auto& curve : family.curves) {
      // One basis per material (its snippet's): the best is the one with the least worst channel.
      std::array<matc::ErrorStats, kBases.size()> errors{};
      std::size_t best_index = 0;
      for (std::size_t b = 0; b < kBases.size(); ++b) {
        errors[b] = fit_error(*curve, kBases[b]);
        by_basis[b].add(errors[b]);
        if (worst_channel(errors[b]) < worst_channel(errors[best_index])) best_index = b;
      }
      best.add(errors[best_index]);
      ++chosen[best_index];
      for (std::size_t b = 0; b < kBases.size(); ++b)
        if (kBases[b] == family.rule) rule.add(errors[b]);
    }
    std::string best_cell = cell(best) + " (";
    for (std::size_t b = 0, listed = 0; b < kBases.size(); ++b) {
      if (chosen[b] == 0) continue;
      best_cell += fmt::format("{}{} {}", listed++ ? ", " : "",
                               matc::runtime::basis_name(kBases[b]), chosen[b]);
    }
    best_cell += ")";
    fmt::print("| {} | `{}` | {} | {} | {} | {} | {} | {} |\n", family.name,
               matc::runtime::basis_name(family.rule), cell(by_basis[0]), cell(by_basis[1]),
               cell(by_basis[2]), cell(by_basis[3]), best_cell, cell(rule));
  }
  return 0;
}
