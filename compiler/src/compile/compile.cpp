#include "compile/compile.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <variant>

#include <fmt/core.h>

#include "compile/film_tables.h"
#include "fit/coefficients.h"
#include "fit/nonnegative_curve.h"
#include "lut/energy.h"
#include "matc/version.h"
#include "optics/coat.h"
#include "optics/spectral.h"
#include "optics/thin_film.h"

namespace matc {
namespace {

// Artistic and ior materials: one complex IOR per channel (F82-tint and spectral have none).
std::optional<std::array<ComplexIor, 3>> per_channel_ior(const MaterialModel& model) {
  std::array<ComplexIor, 3> ior{};
  if (const auto* artistic = std::get_if<ArtisticInput>(&model)) {
    for (std::size_t c = 0; c < 3; ++c) {
      ior[c] = gulbrandsen_to_ior({artistic->reflectivity[c], artistic->edge_tint[c]});
    }
  } else if (const auto* input = std::get_if<IorInput>(&model)) {
    for (std::size_t c = 0; c < 3; ++c)
      ior[c] = {input->n[c], input->k[c]};
  } else {
    return std::nullopt;
  }
  return ior;
}

// Every RGB material's index per channel: artistic and ior as per_channel_ior, F82-tint (which has
// none) as the conductor with its F0 and F(1/7) (docs/coating.md). Spectral materials: nullopt.
std::optional<std::array<ComplexIor, 3>> conductor_per_channel(const MaterialModel& model) {
  if (const auto* f82 = std::get_if<F82TintInput>(&model)) {
    std::array<ComplexIor, 3> ior{};
    for (std::size_t c = 0; c < 3; ++c) {
      const double f_at_mu_bar = f82->tint[c] * fresnel_schlick(kF82MuBar, f82->f0[c]);
      ior[c] = conductor_matching_f82(f82->f0[c], f_at_mu_bar);
    }
    return ior;
  }
  return per_channel_ior(model);
}

ThinFilm thin_film_of(const FilmInput& film) {
  return {film.ior, film.thickness_nm, film.weight};
}

// `curve` with `color`'s gamut mapping applied. `sampled` is the same curve, cached where the
// caller has a cache, to find how far to map; `saturation` gets what the mapping kept (1:
// unchanged).
std::unique_ptr<ReflectanceCurve> apply_gamut_mapping(std::unique_ptr<ReflectanceCurve> curve,
                                                      const ReflectanceCurve& sampled,
                                                      const ColorOptions& color,
                                                      double& saturation) {
  saturation = 1.0;
  if (color.gamut_mapping == GamutMapping::none) return curve;
  const Desaturation mapping =
      desaturation_into_unit_range(sampled, color.working_space, kAccuracySamples);
  saturation = mapping.saturation;
  if (mapping.saturation == 1.0) return curve;
  // The moved curve keeps its address: `sampled` may still refer to it.
  return std::make_unique<TransformedCurve>(std::move(curve), mapping.matrix);
}

}  // namespace

// Its curve is then the bare metal's, bit for bit. A film of the index of the medium it lies in is
// part of that medium: its Airy sum is the bare metal's curve (thin_film_test), so it compiles as
// the bare metal too. That medium is air, or the coat: a film of index 1 under a full coat is an
// air gap, which shows; one of the coat's index is more coat, which does not.
bool has_visible_film(const Material& material) {
  if (!material.film || !(material.film->thickness_nm > 0.0) || !(material.film->weight > 0.0))
    return false;
  const double ior = material.film->ior;
  const bool seen_in_air = !material.coat || material.coat->weight < 1.0;
  return (seen_in_air && ior != 1.0) || (material.coat && ior != material.coat->ior);
}

ColorSpace input_color_space(const Material& material, ColorSpace working_space) {
  return material.color_space.value_or(working_space);
}

std::unique_ptr<ReflectanceCurve> make_working_space_curve(const Material& material,
                                                           ColorSpace working_space) {
  if (const auto* spectral = std::get_if<SpectralInput>(&material.model)) {
    if (has_visible_film(material)) {
      return std::make_unique<ThinFilmCurve>(spectral->spectrum, thin_film_of(*material.film),
                                             working_space);
    }
    return std::make_unique<SpectralCurve>(spectral->spectrum, working_space);
  }
  const ColorSpace space = input_color_space(material, working_space);
  std::unique_ptr<ReflectanceCurve> curve;
  if (has_visible_film(material)) {
    // The channels' band sums use the input space's weights: the index per channel belongs to it.
    curve = std::make_unique<ThinFilmChannelCurve>(*conductor_per_channel(material.model),
                                                   thin_film_of(*material.film), space);
  } else if (const auto* f82 = std::get_if<F82TintInput>(&material.model)) {
    curve = std::make_unique<F82TintCurve>(f82->f0, f82->tint);
  } else {
    curve = std::make_unique<IorCurve>(*per_channel_ior(material.model));
  }
  if (space == working_space) return curve;
  return std::make_unique<TransformedCurve>(std::move(curve), rgb_to_rgb(space, working_space));
}

std::unique_ptr<ReflectanceCurve> make_reflectance_curve(const Material& material,
                                                         const ColorOptions& color) {
  auto curve = make_working_space_curve(material, color.working_space);
  const ReflectanceCurve& sampled = *curve;
  double saturation = 1.0;
  return apply_gamut_mapping(std::move(curve), sampled, color, saturation);
}

std::unique_ptr<ReflectanceCurve> make_metal_in_coat_curve(const Material& material,
                                                           ColorSpace working_space) {
  const CoatInput& coat = material.coat.value();
  const ColorSpace space = std::holds_alternative<SpectralInput>(material.model)
                               ? working_space
                               : input_color_space(material, working_space);
  std::unique_ptr<ReflectanceCurve> metal_in_coat;
  // A film lies between the coat and the metal: seen from the coat, every index relative to it.
  const bool filmed = has_visible_film(material);
  const ThinFilm film =
      filmed ? film_under_coat(thin_film_of(*material.film), coat.ior) : ThinFilm{};
  if (const auto* spectral = std::get_if<SpectralInput>(&material.model)) {
    Spectrum relative = spectral->spectrum;
    for (std::size_t i = 0; i < relative.n.size(); ++i) {
      relative.n[i] /= coat.ior;
      relative.k[i] /= coat.ior;
    }
    if (filmed) {
      metal_in_coat = std::make_unique<ThinFilmCurve>(relative, film, space);
    } else {
      metal_in_coat = std::make_unique<SpectralCurve>(relative, space);
    }
  } else {
    std::array<ComplexIor, 3> ior = *conductor_per_channel(material.model);
    for (auto& channel : ior)
      channel = under_coat(channel, coat.ior);
    if (filmed) {
      metal_in_coat = std::make_unique<ThinFilmChannelCurve>(ior, film, space);
    } else {
      metal_in_coat = std::make_unique<IorCurve>(ior);
    }
  }
  if (space == working_space) return metal_in_coat;
  return std::make_unique<TransformedCurve>(std::move(metal_in_coat),
                                            rgb_to_rgb(space, working_space));
}

std::unique_ptr<ReflectanceCurve> make_under_coat_curve(const Material& material,
                                                        ColorSpace working_space) {
  return std::make_unique<UnderCoatCurve>(make_metal_in_coat_curve(material, working_space),
                                          material.coat.value().ior);
}

namespace {

// The coat's coefficients and how close the layering from them is to the exact layered curve.
// `under_grid` is the metal seen through the coat (make_under_coat_curve) on the accuracy grid.
CompiledCoat compile_coat(const Material& material, const runtime::Coefficients& in_air_fit,
                          const ReflectanceCurve& in_air, const AccuracyGridCurve& under_grid,
                          const runtime::BasisView& basis) {
  const CoatInput& input = *material.coat;
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(basis.kind);
  CompiledCoat coat;
  coat.input = input;
  coat.coefficients.under_coat = solve_coefficients(under_grid, basis);
  coat.under_coat_error =
      measure_accuracy(under_grid, coat.coefficients.under_coat, shader_basis).decomposition;
  const CoatCurve dielectric(input.ior);
  coat.coefficients.coat = solve_coefficients(dielectric, basis)[0];
  coat.coefficients.weight = input.weight;
  coat.coefficients.roughness = input.roughness;
  coat.coefficients.ior = input.ior;
  coat.coefficients.color = input.color;
  coat.coat_max_error =
      measure_accuracy(dielectric,
                       {coat.coefficients.coat, coat.coefficients.coat, coat.coefficients.coat},
                       shader_basis)
          .decomposition.max_abs[0];
  // Evaluated once on the accuracy grid: the loop below and the Schlick and F82-tint rows read it.
  const LayeredCurve layered_exact(in_air, under_grid, input.weight, input.ior, input.color);
  const AccuracyGridCurve layered(layered_exact);
  coat.layered_error = measure_on_accuracy_grid(layered, [&](double mu) {
    return runtime::evaluate_coated_fresnel(in_air_fit, coat.coefficients, shader_basis, mu)
        .total();
  });
  coat.layered_f0 = layered.at(1.0);
  coat.layered_f82 = layered.at(kF82MuBar);
  // Schlick's and F82-tint's rows measure the layered curve itself; the decomposition's row is
  // the two lobes', measured above (the in-air coefficients passed here are not it).
  coat.layered_accuracy = measure_accuracy(layered, in_air_fit, shader_basis);
  coat.layered_accuracy.decomposition = coat.layered_error;
  return coat;
}

// A film under a coat (docs/thin-film.md): the table holds the base lobe, the film in air and under
// the coat layered at every node as the coated shaders layer the basis' values, and the coat's
// layered error becomes both lobes' with that table (the coat lobe's from its coefficients).
void bake_coated_film(const Material& material, const ReflectanceCurve& in_air,
                      const AccuracyGridCurve& under_grid, CompiledMaterial& compiled) {
  const CoatInput& input = *material.coat;
  compiled.film_table = bake_coated_film_table(in_air, under_grid, input);
  const runtime::FilmTable& table = *compiled.film_table;
  const LayeredCurve exact_base(in_air, under_grid, input.weight, input.ior, input.color,
                                LayeredCurve::Part::base);
  compiled.film_table_error = measure_on_accuracy_grid(
      exact_base, [&table](double mu) { return runtime::film_fresnel(table, mu); });
  CompiledCoat& coat = *compiled.coat;
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(compiled.basis);
  const LayeredCurve exact(in_air, under_grid, input.weight, input.ior, input.color);
  coat.layered_error = measure_on_accuracy_grid(
      exact, [&](double mu) { return shader_fresnel(compiled, shader_basis, mu); });
  coat.layered_accuracy.decomposition = coat.layered_error;
}

// A thickness per pixel: the stack over the film's range, each slice the material with that
// thickness (gamut-mapped as the material is); its last slice, the film at the maximum, is the
// film_table the rest of matc reads.
void bake_film_stack_of(const Material& material, const ColorOptions& color,
                        CompiledMaterial& compiled) {
  const auto film_at = [&material, &color](double nm) {
    Material slice = material;
    slice.film->thickness_nm = nm;
    slice.film->thickness_minimum_nm.reset();
    return make_reflectance_curve(slice, color);
  };
  // A film curve sweeps the thicknesses itself (ThinFilmSweep); a curve wrapped in a colour
  // conversion or a gamut mapping is made anew at each thickness.
  const auto at_maximum = film_at(material.film->thickness_nm);
  const auto* sweep = dynamic_cast<const ThinFilmSweep*>(at_maximum.get());
  const FilmRows rows = sweep ? film_rows_by_sweep(*sweep) : film_rows_by_curve(film_at);
  BakedFilmStack baked =
      bake_film_stack(rows, *material.film->thickness_minimum_nm, material.film->thickness_nm);
  compiled.film_stack = std::move(baked.stack);
  compiled.film_stack_error = baked.thickness_error;
  compiled.film_table = compiled.film_stack->slices.back();
}

}  // namespace

static_assert((kAccuracySamples - 1) % (kMinimaxCosines - 1) == 0,
              "the minimax solve's cosines must lie on the accuracy grid AccuracyGridCurve caches");

CompiledMaterial compile_material(const Material& material, const runtime::BasisView& basis,
                                  const ColorOptions& color) {
  CompiledMaterial compiled;
  compiled.material = material;
  compiled.basis = basis.kind;
  compiled.color = color;
  auto unmapped = make_working_space_curve(material, color.working_space);
  // The solve and the accuracy measurement share cosines: evaluate (integrate) the curve once.
  const AccuracyGridCurve unmapped_grid(*unmapped);
  compiled.range = measure_curve_range(unmapped_grid, kAccuracySamples);
  const ReflectanceCurve* const working = unmapped.get();
  const std::unique_ptr<ReflectanceCurve> exact =
      apply_gamut_mapping(std::move(unmapped), unmapped_grid, color, compiled.saturation);
  std::optional<AccuracyGridCurve> mapped_grid;  // only a mapped curve needs its own cache
  if (exact.get() != working) mapped_grid.emplace(*exact);
  const AccuracyGridCurve& curve = mapped_grid ? *mapped_grid : unmapped_grid;
  compiled.coefficients = solve_coefficients(curve, basis);
  compiled.accuracy =
      measure_accuracy(curve, compiled.coefficients, runtime::shipped_shader_basis(basis.kind));
  compiled.f0 = curve.at(1.0);
  compiled.f82 = curve.at(kF82MuBar);
  compiled.average_fresnel =
      average_fresnel(compiled.coefficients, basis_hemispherical_averages(basis));
  compiled.fresnel_nonnegative = fresnel_provably_nonnegative(
      compiled.coefficients, runtime::shipped_shader_basis(basis.kind));
  // The per-channel IOR describes the curve only where no matrix mixed the channels and no film
  // lies over the metal.
  const bool channels_kept =
      input_color_space(material, color.working_space) == color.working_space &&
      compiled.saturation == 1.0 && !has_visible_film(material);
  if (const auto ior = per_channel_ior(material.model); ior && channels_kept) {
    compiled.ior = *ior;
    std::array<ArtisticParameters, 3> artistic{};
    for (std::size_t c = 0; c < 3; ++c)
      artistic[c] = ior_to_gulbrandsen((*ior)[c]);
    compiled.artistic = artistic;
  }
  if (material.coat) {
    // The metal seen through the coat, evaluated once on the accuracy grid: the coat's fit and a
    // film's table under it read it.
    const auto under = make_under_coat_curve(material, color.working_space);
    const AccuracyGridCurve under_grid(*under);
    compiled.coat = compile_coat(material, compiled.coefficients, curve, under_grid, basis);
    if (has_visible_film(material)) bake_coated_film(material, curve, under_grid, compiled);
  } else if (has_visible_film(material)) {
    if (material.film->thickness_minimum_nm)
      bake_film_stack_of(material, color, compiled);
    else
      compiled.film_table = bake_film_table(curve);
    // The table the shaders read without a thickness texture, against the exact curve.
    const runtime::FilmTable& table = *compiled.film_table;
    compiled.film_table_error = measure_on_accuracy_grid(
        curve, [&table](double mu) { return runtime::film_fresnel(table, mu); });
  }
  return compiled;
}

const ErrorStats& shader_fresnel_error(const CompiledMaterial& compiled) {
  return compiled.film_table ? compiled.film_table_error : compiled.accuracy.decomposition;
}

runtime::CoatedFresnel shader_coated_fresnel(const CompiledMaterial& compiled,
                                             const runtime::ShaderBasis& basis, double mu) {
  const runtime::CoatCoefficients& coat = compiled.coat.value().coefficients;
  return compiled.film_table
             ? runtime::evaluate_film_coated_fresnel(*compiled.film_table, coat, basis, mu)
             : runtime::evaluate_coated_fresnel(compiled.coefficients, coat, basis, mu);
}

Rgb shader_fresnel(const CompiledMaterial& compiled, const runtime::ShaderBasis& basis, double mu) {
  if (compiled.coat) return shader_coated_fresnel(compiled, basis, mu).total();
  if (compiled.film_table) return runtime::film_fresnel(*compiled.film_table, mu);
  return runtime::evaluate_fresnel(compiled.coefficients, basis, mu);
}

}  // namespace matc

namespace matc {

void warn_if_poor_fit(const CompiledMaterial& compiled, Diagnostics& diagnostics) {
  // A coated material is judged whole (docs/coating.md): under a full coat its bare curve, which
  // a high-reflectivity, low-edge-tint metal makes hard to fit, is never seen.
  // A filmed metal's shaders read its table, which holds the film within 0.003 (FilmTables.*);
  // with a thickness per pixel, the stack may hold the thickness axis less closely.
  if (compiled.film_stack && compiled.film_stack_error > kPoorFilmStackError) {
    diagnostics.warning(
        compiled.material.name_location, "film",
        fmt::format("thickness range {}-{} nm: its {} slices hold F within {:.3f} between them "
                    "(the target is {}: a wide range of a high-index film needs more than {} "
                    "slices)",
                    compiled.film_stack->minimum_nm, compiled.film_stack->maximum_nm,
                    compiled.film_stack->slices.size(), compiled.film_stack_error,
                    kPoorFilmStackError, kMaxFilmStackSlices),
        "narrow the thickness range to the one the texture uses (docs/thin-film.md)");
  }
  if (compiled.film_table) return;
  const FitAccuracy& accuracy = compiled.coat ? compiled.coat->layered_accuracy : compiled.accuracy;
  const auto worst = [](const ErrorStats& stats) {
    return *std::max_element(stats.max_abs.begin(), stats.max_abs.end());
  };
  const double ours = worst(accuracy.decomposition);
  if (ours <= kPoorFitMaxError) return;
  const double schlick = worst(accuracy.schlick);
  const double f82 = worst(accuracy.f82_tint);
  std::string advice;
  const bool f82_material = std::holds_alternative<F82TintInput>(compiled.material.model);
  if (std::holds_alternative<ArtisticInput>(compiled.material.model)) {
    advice =
        "high reflectivity with a low edge tint makes curves like a high-index dielectric's, which "
        "no 4-term basis follows: lower the reflectivity or raise the edge tint, or give the "
        "measured n, k (\"ior\" or \"spectral\")";
  } else if (f82_material) {
    advice =
        "a tint well below 1 dips F82-tint's curve near grazing in a shape a basis fitted to "
        "conductors does not follow (docs/accuracy.md): compile with --basis auto, which gives "
        "it the f82 basis that holds every F82-tint curve (or --basis f82 for the whole build), "
        "or raise the tint, or give the metal's n, k (\"ior\" or \"spectral\")";
  } else {
    advice = "check the input values; curves this far from measured metals fit poorly";
  }
  if (!f82_material && (f82 < ours || schlick < ours)) {
    advice += fmt::format("; for this curve {} is closer", f82 <= schlick ? "F82-tint" : "Schlick");
  }
  diagnostics.warning(
      compiled.material.name_location, std::string(model_key(compiled.material.model)),
      fmt::format("poor fit{}: max |F - exact| = {:.3f} (Schlick {:.3f}, F82-tint {:.3f}; the "
                  "measured metals stay under 0.02)",
                  compiled.coat ? " of the coated surface" : "", ours, schlick, f82),
      advice);
}

void note_if_out_of_unit_range(const CompiledMaterial& compiled, Diagnostics& diagnostics) {
  const CurveRange& range = compiled.range;
  if (range.within_unit_range()) return;
  const double high = *std::max_element(range.max.begin(), range.max.end());
  const double low = *std::min_element(range.min.begin(), range.min.end());
  std::string extent = high > 1.0 ? fmt::format("reaches {:.4f}", high) : "";
  if (low < 0.0) extent += fmt::format("{}falls to {:.4f}", extent.empty() ? "" : " and ", low);
  const std::string space(color_space_name(compiled.color.working_space));
  // A film's interference colours leave the gamut whatever the model (IridescenceMetallicSpheres'
  // grey F82-tint metals, tint 1, under films of 100-700 nm): only a bare F82-tint curve's dip
  // below 0 is its correction term's.
  const bool model_overshoot = low < 0.0 &&
                               std::holds_alternative<F82TintInput>(compiled.material.model) &&
                               !compiled.film_table;
  std::string message = fmt::format(
      "its Fresnel curve {} in {} ({})", extent, space,
      model_overshoot ? "F82-tint's correction term overshoots below 0 for a tint this low"
                      : "a colour outside the space's gamut, not an error in the data");
  if (compiled.color.gamut_mapping == GamutMapping::desaturate) {
    message +=
        fmt::format("; desaturated to {:.4f} of its chroma at every angle", compiled.saturation);
  }
  std::string advice;
  if (model_overshoot) {
    advice = "engines clamp it at 0; a tint nearer 1 avoids it";
  } else if (compiled.color.gamut_mapping == GamutMapping::none) {
    advice =
        "keep it for engines that do not clamp; --gamut-mapping desaturate for those that do "
        "(docs/color-spaces.md)";
  }
  diagnostics.note(compiled.material.name_location, "color", std::move(message), std::move(advice));
}

}  // namespace matc
