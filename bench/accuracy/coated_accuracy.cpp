// Prints the coated-metal accuracy tables of docs/coating.md: every measured metal and a grid of
// artistic inputs under clear coats of index 1.3, 1.5 and 1.6 (and a tinted one), compiled the
// way matc compiles a `coat` block, against the exact layered reflectance (smooth interfaces,
// exact Fresnel at both). Beside ours: the engines' shortcuts, F0 converted into the coat's
// medium with Schlick (Filament) and the metal's curve in air left as it is (three.js,
// Babylon.js), each under the same coat lobe and attenuation.
// Run through bench/accuracy/update-docs.sh; tests/scripts/check_docs_block.sh keeps the docs in
// sync.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string_view>

#include <fmt/core.h>

#include "compile/compile.h"
#include "error_totals.h"
#include "fit/coefficients.h"
#include "lut/layered_reference.h"
#include "lut/preintegrate.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/shipped_bases.h"
#include "material/material_input.h"
#include "optics/coat.h"
#include "optics/gulbrandsen.h"
#include "optics/presets.h"

namespace {

using matc::Rgb;
using matc::bench::Totals;

constexpr std::array<double, 3> kCoatIors = {1.3, 1.5, 1.6};
constexpr std::size_t kSamples = matc::kAccuracySamples;

struct CoatedErrors {
  matc::ErrorStats under_coat;  // our under-coat fit
  matc::ErrorStats layered;     // ours, layered, against the exact layered curve
  Rgb f0_in_coat_schlick{};     // max error of the engine shortcuts, same layering
  Rgb in_air{};
};

// The engines' shortcuts under the same layering: coat lobe w F_coat (exact), base
// mix(base in air, (1 - F_coat)^2 v / (1 - F_coat v), w) with v their stand-in for the metal under
// the coat.
CoatedErrors measure(const matc::Material& material) {
  const auto& basis = matc::runtime::shipped_basis(matc::runtime::kDefaultBasis);
  const matc::CompiledMaterial compiled = matc::compile_material(material, basis);
  const matc::CompiledCoat& coat = *compiled.coat;
  CoatedErrors errors{coat.under_coat_error, coat.layered_error, {}, {}};
  const auto in_air = matc::make_reflectance_curve(material);
  const auto under = matc::make_under_coat_curve(material, matc::kDefaultColorSpace);
  const matc::LayeredCurve layered(*in_air, *under, coat.input.weight, coat.input.ior,
                                   coat.input.color);
  const Rgb f0 = in_air->at(1.0);
  for (std::size_t j = 0; j < kSamples; ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(kSamples - 1);
    const double f_coat = matc::coat_fresnel(mu, coat.input.ior);
    const double mu_inside = matc::refracted_cosine(mu, coat.input.ior);
    const Rgb exact = layered.at(mu);
    const Rgb air = in_air->at(mu);
    for (std::size_t c = 0; c < 3; ++c) {
      const double w = coat.input.weight;
      const double tint = matc::coat_round_trip_transmittance(coat.input.color[c], mu_inside);
      const auto total = [&](double under_coat) {
        return w * f_coat + (1.0 - w) * air[c] +
               w * matc::coated_base_reflectance(f_coat, tint * under_coat);
      };
      const double schlick =
          matc::fresnel_schlick(mu, matc::f0_seen_from_coat(f0[c], coat.input.ior));
      errors.f0_in_coat_schlick[c] =
          std::max(errors.f0_in_coat_schlick[c], std::abs(total(schlick) - exact[c]));
      errors.in_air[c] = std::max(errors.in_air[c], std::abs(total(air[c]) - exact[c]));
    }
  }
  return errors;
}

matc::Material coated(matc::MaterialModel model, double coat_ior, const Rgb& color) {
  matc::Material material;
  material.name = "coated";
  material.model = std::move(model);
  material.coat = matc::CoatInput{1.0, coat_ior, 0.0, color};
  return material;
}

void print_measured() {
  fmt::print(
      "| metal | coat index | ours: under-coat fit max | ours: layered max | F0-in-coat Schlick "
      "max | metal's curve in air max |\n|---|---:|---:|---:|---:|---:|\n");
  Totals under, layered, schlick, air;
  Totals tinted_layered;
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    if (!preset.caveat.empty()) continue;  // as the uncoated tables: the reliable metals only
    for (const double coat_ior : kCoatIors) {
      const CoatedErrors e = measure(coated(matc::SpectralInput{std::string(preset.symbol), "", "",
                                                                "", matc::preset_spectrum(preset)},
                                            coat_ior, {1.0, 1.0, 1.0}));
      under.add(e.under_coat);
      layered.add(e.layered);
      schlick.add({e.f0_in_coat_schlick, {}});
      air.add({e.in_air, {}});
      if (coat_ior == 1.5) {
        fmt::print("| {} {} | {:.1f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} |\n", preset.symbol,
                   preset.name, coat_ior, matc::worst_channel(e.under_coat.max_abs),
                   matc::worst_channel(e.layered.max_abs),
                   matc::worst_channel(e.f0_in_coat_schlick), matc::worst_channel(e.in_air));
      }
    }
    // A tinted coat: the round-trip colour of a warm lacquer.
    const CoatedErrors tinted = measure(coated(
        matc::SpectralInput{std::string(preset.symbol), "", "", "", matc::preset_spectrum(preset)},
        1.5, {0.9, 0.6, 0.3}));
    tinted_layered.add(tinted.layered);
  }
  fmt::print(
      "\nOver the {} curves of {} measured metals (RGB each) under clear coats of index 1.3, 1.5 "
      "and 1.6 ({} curves), against the exact layered reflectance:\n\n",
      under.curves / 3 / 3 * 3, under.curves / 9, under.curves);
  fmt::print(
      "| model | worst-channel max error | mean of per-curve max |\n|---|---:|---:|\n"
      "| ours: the under-coat curve alone, against its exact curve | {:.4f} | {:.4f} |\n"
      "| ours: coat lobe + layered base | {:.4f} | {:.4f} |\n"
      "| ours, layered, under a tinted coat (1.5, colour 0.9, 0.6, 0.3) | {:.4f} | {:.4f} |\n"
      "| F0 converted into the coat, Schlick (Filament) | {:.4f} | {:.4f} |\n"
      "| the metal's curve in air (three.js, Babylon.js) | {:.4f} | {:.4f} |\n",
      under.worst, under.mean(), layered.worst, layered.mean(), tinted_layered.worst,
      tinted_layered.mean(), schlick.worst, schlick.mean(), air.worst, air.mean());
}

// Grey artistic inputs under a clear coat of 1.5: our layered max error over an (r, g) grid.
void print_artistic_grid() {
  constexpr std::array<double, 7> kEdgeTints = {0.0, 0.2, 0.4, 0.6, 0.8, 0.9, 1.0};
  fmt::print("\nGrey artistic inputs under a clear coat of index 1.5, ours layered:\n\n| r \\ g |");
  for (const double g : kEdgeTints)
    fmt::print(" {:.1f} |", g);
  fmt::print("\n|---:|");
  for (std::size_t i = 0; i < kEdgeTints.size(); ++i)
    fmt::print("---:|");
  fmt::print("\n");
  for (const double r : {0.05, 0.2, 0.4, 0.6, 0.8, 0.9, 0.95, 0.99}) {
    fmt::print("| {:.2f} |", r);
    for (const double g : kEdgeTints) {
      const CoatedErrors e =
          measure(coated(matc::ArtisticInput{{r, r, r}, {g, g, g}}, 1.5, {1.0, 1.0, 1.0}));
      fmt::print(" {:.4f} |", e.layered.max_abs[0]);
    }
    fmt::print("\n");
  }
}

// What the choices in docs/coating.md avoid, each fitted with the default basis and measured
// against its own exact curve over 2001 cosines, worst channel over the measured metals under a
// coat of 1.5: the metal/coat curve over its own cosines (the `ior` input with n / 1.5, k / 1.5),
// the tint folded into the under-coat curve (a warm lacquer), the coat's transmission and the
// bounces folded in too. Then the coat's own dielectric fit by index.
class FoldedCurve final : public matc::ReflectanceCurve {
 public:
  FoldedCurve(const matc::ReflectanceCurve& under, double coat_ior, const Rgb& color, bool bounces)
      : under_(under), coat_ior_(coat_ior), color_(color), bounces_(bounces) {}
  Rgb at(double mu) const override {
    const double mu_inside = matc::refracted_cosine(mu, coat_ior_);
    const double f = matc::coat_fresnel(mu, coat_ior_);
    const Rgb v = under_.at(mu);
    Rgb out{};
    for (std::size_t c = 0; c < 3; ++c) {
      const double tinted = matc::coat_round_trip_transmittance(color_[c], mu_inside) * v[c];
      out[c] = bounces_ ? matc::coated_base_reflectance(f, tinted) : tinted;
    }
    return out;
  }
  std::optional<Rgb> grazing_value() const override { return at(0.0); }

 private:
  const matc::ReflectanceCurve& under_;
  double coat_ior_;
  Rgb color_;
  bool bounces_;
};

void print_alternatives() {
  const auto& basis = matc::runtime::shipped_basis(matc::runtime::kDefaultBasis);
  const auto fit_error = [&](const matc::ReflectanceCurve& curve) {
    const matc::AccuracyGridCurve grid(curve);
    return matc::worst_channel(
        matc::measure_accuracy(grid, matc::solve_coefficients(grid, basis),
                               matc::runtime::shipped_shader_basis(basis.kind))
            .decomposition.max_abs);
  };
  double own_cosines = 0.0, seen_part = 0.0, tint_folded = 0.0, all_folded = 0.0;
  for (const matc::MetalPreset& preset : matc::metal_presets()) {
    if (!preset.caveat.empty()) continue;
    const matc::Material material = coated(
        matc::SpectralInput{std::string(preset.symbol), "", "", "", matc::preset_spectrum(preset)},
        1.5, {1.0, 1.0, 1.0});
    const auto metal_in_coat = matc::make_metal_in_coat_curve(material, matc::kDefaultColorSpace);
    const auto under = matc::make_under_coat_curve(material, matc::kDefaultColorSpace);
    const matc::TabulatedCurve under_table(*under);
    own_cosines = std::max(own_cosines, fit_error(*metal_in_coat));
    seen_part = std::max(seen_part, fit_error(*under));
    tint_folded =
        std::max(tint_folded, fit_error(FoldedCurve(under_table, 1.5, {0.9, 0.6, 0.3}, false)));
    all_folded =
        std::max(all_folded, fit_error(FoldedCurve(under_table, 1.5, {1.0, 1.0, 1.0}, true)));
  }
  fmt::print(
      "\n| fitted curve (coat of index 1.5, measured metals) | worst-channel max error |\n"
      "|---|---:|\n"
      "| the metal/coat curve over its own cosines in [0, 1] | {:.4f} |\n"
      "| ours: the part seen through the coat, over the cosine in air | {:.4f} |\n"
      "| the same with a warm tint (0.9, 0.6, 0.3) folded in | {:.4f} |\n"
      "| the same with the coat's transmission and the bounces folded in (clear) | {:.4f} |\n",
      own_cosines, seen_part, tint_folded, all_folded);
  fmt::print("\n| coat index | 1.05 | 1.1 | 1.3 | 1.5 | 1.6 | 2.0 | 3.0 |\n|---|");
  for (int i = 0; i < 7; ++i)
    fmt::print("---:|");
  fmt::print("\n| the coat's Fresnel, max error |");
  for (const double ior : {1.05, 1.1, 1.3, 1.5, 1.6, 2.0, 3.0})
    fmt::print(" {:.4f} |", fit_error(matc::CoatCurve(ior)));
  fmt::print("\n");
}

// The coated examples as compiled (`matc` defaults): F against the exact layered curve, Fbar (one
// fetch per lobe) against the split-sum layering with exact curves and against the Monte-Carlo
// layered reference, over view cosines at the material's own roughness.
void print_examples(std::span<char*> files) {
  const auto& basis = matc::runtime::shipped_basis(matc::runtime::kDefaultBasis);
  const matc::Lut lut = matc::preintegrate_lut(basis, {});
  fmt::print(
      "| material | coat (index, roughness, colour) | F max error | Fbar max error, split-sum "
      "layering | Fbar against the Monte-Carlo layered reference: max, at NdotV | the same at "
      "NdotV "
      "1 |\n"
      "|---|---|---:|---:|---:|---:|\n");
  for (char* file : files) {
    const matc::MaterialInput input = matc::read_material_input(file);
    for (const matc::Material& material : input.materials) {
      if (!material.coat) continue;
      const matc::CompiledMaterial compiled = matc::compile_material(material, basis);
      const matc::CompiledCoat& coat = *compiled.coat;
      const auto in_air = matc::make_reflectance_curve(material);
      const auto under = matc::make_under_coat_curve(material, matc::kDefaultColorSpace);
      const auto metal_in_coat = matc::make_metal_in_coat_curve(material, matc::kDefaultColorSpace);
      const matc::TabulatedCurve in_air_table(*in_air), under_table(*under);
      const double roughness = material.roughness.value_or(0.0);
      double split_sum = 0.0, monte_carlo = 0.0, worst_ndotv = 0.0, head_on = 0.0;
      for (const double ndotv : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}) {
        const Rgb ours = matc::runtime::evaluate_coated_fbar(
                             compiled.coefficients, coat.coefficients, lut.view(), ndotv, roughness)
                             .total();
        const Rgb reference =
            matc::layered_split_sum(in_air_table, under_table, coat.input, ndotv, roughness);
        const matc::LayeredEstimate layered =
            matc::layered_albedo({*in_air, *metal_in_coat, coat.input, roughness}, ndotv, 1u << 15);
        for (std::size_t c = 0; c < 3; ++c) {
          split_sum = std::max(split_sum, std::abs(ours[c] - reference[c]));
          const double from_monte_carlo = std::abs(ours[c] - layered.mean[c]);
          if (ndotv == 1.0) head_on = std::max(head_on, from_monte_carlo);
          if (from_monte_carlo > monte_carlo) {
            monte_carlo = from_monte_carlo;
            worst_ndotv = ndotv;
          }
        }
      }
      fmt::print(
          "| {} | {}, {:.2f}, ({:.2f}, {:.2f}, {:.2f}) | {:.4f} | {:.4f} | {:.3f} at {:.2f} | "
          "{:.3f} |\n",
          material.name, coat.input.ior, coat.input.roughness, coat.input.color[0],
          coat.input.color[1], coat.input.color[2], matc::worst_channel(coat.layered_error.max_abs),
          split_sum, monte_carlo, worst_ndotv, head_on);
    }
  }
}

}  // namespace

// No arguments: the measured metals' and the artistic grid's tables. --examples FILE...: the
// coated examples' table.
int main(int argc, char** argv) {
  if (argc > 1 && std::string_view(argv[1]) == "--examples") {
    print_examples(std::span<char*>(argv + 2, static_cast<std::size_t>(argc - 2)));
    return 0;
  }
  print_measured();
  print_artistic_grid();
  print_alternatives();
  return 0;
}
