#include "matc/compile.h"

#include <algorithm>
#include <filesystem>
#include <variant>

#include <fmt/core.h>

#include "matc/fit/coefficients.h"
#include "matc/lut/energy.h"
#include "matc/optics/spectral.h"
#include "matc/version.h"

namespace matc {
namespace {

using nlohmann::ordered_json;

std::array<ComplexIor, 3> per_channel_ior(const MaterialModel& model) {
  std::array<ComplexIor, 3> ior{};
  if (const auto* artistic = std::get_if<ArtisticInput>(&model)) {
    for (std::size_t c = 0; c < 3; ++c) {
      ior[c] = gulbrandsen_to_ior({artistic->reflectivity[c], artistic->edge_tint[c]});
    }
  } else if (const auto* input = std::get_if<IorInput>(&model)) {
    for (std::size_t c = 0; c < 3; ++c)
      ior[c] = {input->n[c], input->k[c]};
  }
  return ior;
}

ordered_json rgb_json(const Rgb& rgb) {
  return ordered_json::array({rgb[0], rgb[1], rgb[2]});
}

ordered_json error_stats_json(const ErrorStats& stats) {
  return {{"max", rgb_json(stats.max_abs)}, {"rms", rgb_json(stats.rms)}};
}

ordered_json input_json(const Material& material) {
  ordered_json input;
  if (const auto* artistic = std::get_if<ArtisticInput>(&material.model)) {
    input = {{"reflectivity", rgb_json(artistic->reflectivity)},
             {"edge_tint", rgb_json(artistic->edge_tint)}};
  } else if (const auto* ior = std::get_if<IorInput>(&material.model)) {
    input = {{"n", rgb_json(ior->n)}, {"k", rgb_json(ior->k)}};
  } else {
    const auto& spectral = std::get<SpectralInput>(material.model);
    input = spectral.preset.empty() ? ordered_json{{"file", spectral.file}}
                                    : ordered_json{{"preset", spectral.preset}};
  }
  return {{std::string(model_key(material.model)), input}};
}

}  // namespace

std::unique_ptr<ReflectanceCurve> make_reflectance_curve(const Material& material) {
  if (const auto* spectral = std::get_if<SpectralInput>(&material.model)) {
    return std::make_unique<SpectralCurve>(spectral->spectrum);
  }
  return std::make_unique<IorCurve>(per_channel_ior(material.model));
}

static_assert((kAccuracySamples - 1) % (kMinimaxCosines - 1) == 0,
              "the minimax solve's cosines must lie on the accuracy grid AccuracyGridCurve caches");

CompiledMaterial compile_material(const Material& material, const runtime::BasisView& basis) {
  const auto exact = make_reflectance_curve(material);
  // The solve and the accuracy measurement share cosines: evaluate (integrate) the curve once.
  const AccuracyGridCurve curve(*exact);
  CompiledMaterial compiled;
  compiled.material = material;
  compiled.coefficients = solve_coefficients(curve, basis);
  compiled.accuracy =
      measure_accuracy(curve, compiled.coefficients, runtime::shipped_basis_polynomial(basis.kind));
  compiled.f0 = curve.at(1.0);
  compiled.f82 = curve.at(kF82MuBar);
  compiled.average_fresnel =
      average_fresnel(compiled.coefficients, basis_hemispherical_averages(basis));
  if (!std::holds_alternative<SpectralInput>(material.model)) {
    compiled.ior = per_channel_ior(material.model);
    std::array<ArtisticParameters, 3> artistic{};
    for (std::size_t c = 0; c < 3; ++c)
      artistic[c] = ior_to_gulbrandsen((*compiled.ior)[c]);
    compiled.artistic = artistic;
  }
  return compiled;
}

ordered_json compiled_material_json(const CompiledMaterial& compiled,
                                    const runtime::BasisView& basis) {
  const Material& material = compiled.material;
  ordered_json out;
  out["matc_version"] = kVersion;
  out["name"] = material.name;
  // The file name only, so the output does not depend on where the build ran.
  out["source"] = std::filesystem::path(material.source_path).filename().generic_string();
  out["input"] = input_json(material);
  out["roughness"] = material.roughness ? ordered_json(*material.roughness) : ordered_json();

  ordered_json resolved;
  if (compiled.ior) {
    const auto& ior = *compiled.ior;
    const auto& artistic = *compiled.artistic;
    resolved["ior"] = {{"n", rgb_json({ior[0].n, ior[1].n, ior[2].n})},
                       {"k", rgb_json({ior[0].k, ior[1].k, ior[2].k})}};
    resolved["artistic"] = {
        {"reflectivity",
         rgb_json({artistic[0].reflectivity, artistic[1].reflectivity, artistic[2].reflectivity})},
        {"edge_tint",
         rgb_json({artistic[0].edge_tint, artistic[1].edge_tint, artistic[2].edge_tint})}};
  } else {
    const auto& spectrum = std::get<SpectralInput>(material.model).spectrum;
    resolved["spectral"] = {
        {"data_range_nm", {spectrum.wavelength_nm.front(), spectrum.wavelength_nm.back()}},
        {"data_samples", spectrum.wavelength_nm.size()},
        {"integration",
         "CIE 1931 2-degree observer x D65, 360-830 nm at 1 nm, linear sRGB, "
         "normalised so a perfect mirror is (1, 1, 1)"}};
  }
  resolved["F0"] = rgb_json(compiled.f0);
  resolved["F82"] = rgb_json(compiled.f82);
  out["resolved"] = resolved;

  ordered_json basis_json = {{"name", runtime::basis_name(basis.kind)},
                             {"samples", basis.samples()}};
  if (basis.kind == runtime::BasisKind::paper) {
    basis_json["solve"] = "probes";
    basis_json["probes_mu"] = {basis.probe_mu(0), basis.probe_mu(1)};
  } else {
    basis_json["solve"] = "minimax";
    basis_json["minimax_cosines"] = kMinimaxCosines;
  }
  out["basis"] = std::move(basis_json);
  ordered_json coefficients = ordered_json::array();
  for (const auto& channel : compiled.coefficients) {
    coefficients.push_back({channel[0], channel[1], channel[2], channel[3]});
  }
  out["coefficients"] = coefficients;
  out["energy_compensation"] = {{"F_avg", rgb_json(compiled.average_fresnel)}};
  out["accuracy"] = {{"samples", compiled.accuracy.samples},
                     {"metric",
                      "absolute error vs the exact Fresnel curve over mu = cos(theta) "
                      "uniform in [0, 1]"},
                     {"decomposition", error_stats_json(compiled.accuracy.decomposition)},
                     {"schlick", error_stats_json(compiled.accuracy.schlick)},
                     {"f82_tint", error_stats_json(compiled.accuracy.f82_tint)}};
  return out;
}

}  // namespace matc

namespace matc {

void warn_if_poor_fit(const CompiledMaterial& compiled, Diagnostics& diagnostics) {
  const FitAccuracy& accuracy = compiled.accuracy;
  const auto worst = [](const ErrorStats& stats) {
    return *std::max_element(stats.max_abs.begin(), stats.max_abs.end());
  };
  const double ours = worst(accuracy.decomposition);
  if (ours <= kPoorFitMaxError) return;
  const double schlick = worst(accuracy.schlick);
  const double f82 = worst(accuracy.f82_tint);
  std::string advice;
  if (std::holds_alternative<ArtisticInput>(compiled.material.model)) {
    advice =
        "high reflectivity with a low edge tint makes curves like a high-index dielectric's, which "
        "no 4-term basis follows: lower the reflectivity or raise the edge tint, or give the "
        "measured n, k (\"ior\" or \"spectral\")";
  } else {
    advice = "check the n, k values; curves this far from measured metals fit poorly";
  }
  if (f82 < ours || schlick < ours) {
    advice += fmt::format("; for this curve {} is closer", f82 <= schlick ? "F82-tint" : "Schlick");
  }
  diagnostics.warning(
      compiled.material.name_location, std::string(model_key(compiled.material.model)),
      fmt::format("poor fit: max |F - exact| = {:.3f} (Schlick {:.3f}, F82-tint {:.3f}; the "
                  "measured metals stay under 0.02)",
                  ours, schlick, f82),
      advice);
}

}  // namespace matc
