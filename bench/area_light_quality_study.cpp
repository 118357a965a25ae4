// The quality level's study of docs/ltc.md (issue #31): on random quad lights around a shading
// point (random view, roughness 0.15-0.85; the quads of lobe_polygons.h from a seed no fit used,
// half centred where the lobe reflects, half anywhere), the error of each area-light estimate
// against the exact integral (GGX, the material's exact Fresnel curve, Monte Carlo with MIS):
// radiance-weighted (sum |L - ref| / sum ref) per channel, and per light (the mean of
// |L - ref| / ref over lights with ref > 1e-3). Estimates: LTC x Schlick's, LTC x ours (one
// shape, the default), the quality level (ltc_following.h), and four that split the error: the
// one shape x the exact preintegrated Fresnel and the exact lobe integral x the exact Fbar (each
// of the default's two errors alone), the quality level's shape x the exact Fbar and the exact
// lobe integral x the quality level's Fresnel (each of its two alone). With --compare-weights,
// the quality level with other blend weights for its shape and its Fresnel.
//   matc_area_light_quality_study [--views N] [--samples N] [--compare-weights] FILES...
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <future>
#include <random>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "compile/compile.h"
#include "emit/build.h"
#include "ltc/area_light_reference.h"
#include "ltc/lobe_polygons.h"
#include "lut/comparison_lobes.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/ltc_following.h"
#include "material/parse.h"

namespace {

using matc::Rgb;
using matc::Vec3;

constexpr std::uint64_t kViewSeed = 31;
constexpr double kLowestRoughness = 0.15, kHighestRoughness = 0.85;
constexpr double kLitThreshold = 1e-3;  // per-light errors only where ref > this

enum Estimate {
  schlick,
  ours,
  quality,
  one_shape_exact_fbar,
  lobe_exact_fbar,
  quality_shape_exact_fbar,
  lobe_quality_fresnel,
  kEstimates
};
const std::array<const char*, kEstimates> kEstimateNames = {"LTC x Schlick's",
                                                            "LTC x ours (one shape, default)",
                                                            "quality level",
                                                            "one shape x exact Fbar",
                                                            "exact lobe x exact Fbar",
                                                            "quality shape x exact Fbar",
                                                            "exact lobe x quality Fresnel"};

// Other blend weights for the quality level (--compare-weights), from I_ltc and the light's
// extent q = sqrt(|f|) (the shipped shape weight is s = q (2 - q)).
struct Weight {
  const char* name;
  double (*of)(double integral, double extent);
};
const std::array<Weight, 5> kFresnelWeights = {
    {{"0 (F at the light alone)", [](double, double) { return 0.0; }},
     {"I^2", [](double i, double) { return i * i; }},
     {"I (shipped)", [](double i, double) { return i; }},
     {"sqrt(I)", [](double i, double) { return std::sqrt(i); }},
     {"s", [](double, double q) { return q * (2.0 - q); }}}};
const std::array<Weight, 7> kShapeWeights = {
    {{"1 (the one shape)", [](double, double) { return 1.0; }},
     {"I", [](double i, double) { return i; }},
     {"I^(1/4)", [](double i, double) { return std::sqrt(std::sqrt(i)); }},
     {"q = sqrt(|f|)", [](double, double q) { return q; }},
     {"q^2", [](double, double q) { return q * q; }},
     {"sqrt(q)", [](double, double q) { return std::sqrt(q); }},
     {"q (2 - q) (shipped)", [](double, double q) { return q * (2.0 - q); }}}};

// Per roughness band, per set of lights (0 centred on the lobe, 1 anywhere): sums per channel.
constexpr std::array<std::array<double, 2>, 3> kBands = {{{0.15, 0.4}, {0.4, 0.6}, {0.6, 0.85}}};
struct Sums {
  std::array<Rgb, kEstimates> error{};
  std::array<Rgb, kEstimates> relative{};
  std::array<Rgb, kFresnelWeights.size()> fresnel_weight_error{};
  std::array<Rgb, kShapeWeights.size()> shape_weight_error{};
  Rgb reference{};
  std::array<std::size_t, 3> lit{};
  std::size_t lights = 0;

  void add(const Sums& other) {
    for (std::size_t c = 0; c < 3; ++c) {
      for (std::size_t k = 0; k < kEstimates; ++k) {
        error[k][c] += other.error[k][c];
        relative[k][c] += other.relative[k][c];
      }
      for (std::size_t k = 0; k < kFresnelWeights.size(); ++k)
        fresnel_weight_error[k][c] += other.fresnel_weight_error[k][c];
      for (std::size_t k = 0; k < kShapeWeights.size(); ++k)
        shape_weight_error[k][c] += other.shape_weight_error[k][c];
      reference[c] += other.reference[c];
      lit[c] += other.lit[c];
    }
    lights += other.lights;
  }
};
using MaterialSums = std::array<std::array<Sums, 2>, kBands.size()>;  // [band][set]

struct Inputs {
  const matc::Build& build;
  const matc::Lut& schlick_lut;
  std::size_t views;
  std::size_t samples;
};

MaterialSums study_material(const Inputs& inputs, const matc::Material& material) {
  const matc::CompiledMaterial compiled = matc::compile_material(material, inputs.build.basis());
  const auto curve = matc::make_reflectance_curve(compiled.material, compiled.color);
  const matc::TabulatedCurve exact(*curve);
  const matc::runtime::LutView lut = inputs.build.stored_lut().view();
  const matc::runtime::LtcTableView ltc = matc::runtime::shipped_ltc_table();
  const matc::runtime::ShaderBasis& basis =
      matc::runtime::shipped_shader_basis(inputs.build.options().basis);
  const matc::FresnelAtCosine one = [](double) { return Rgb{1.0, 1.0, 1.0}; };
  // The same views for every material: mt19937_64 and this conversion are fully specified.
  std::mt19937_64 random(kViewSeed);
  const auto uniform = [&] { return static_cast<double>(random() >> 11) * 0x1p-53; };
  MaterialSums sums{};
  for (std::size_t v = 0; v < inputs.views; ++v) {
    const double ndotv = 0.05 + 0.95 * uniform();
    const double roughness = kLowestRoughness + (kHighestRoughness - kLowestRoughness) * uniform();
    std::size_t band = 0;
    while (band + 1 < kBands.size() && roughness >= kBands[band][1])
      ++band;
    const matc::GgxLobe lobe(ndotv, roughness);
    const Rgb fbar_exact = matc::SplitSumEstimator(ndotv, roughness).integrate(exact);
    const auto bbar = matc::runtime::sample_lut(lut, ndotv, roughness);
    const double albedo = bbar[0];
    const Rgb fbar = matc::runtime::evaluate_fbar(compiled.coefficients, lut, ndotv, roughness);
    const auto lobes = matc::runtime::sample_lut(inputs.schlick_lut.view(), ndotv, roughness);
    const matc::runtime::LtcInverse inverse = matc::runtime::sample_ltc(ltc, ndotv, roughness);
    const std::vector<matc::LobePolygon> quads = matc::lobe_polygons(
        lobe, 1.0, matc::lobe_polygon_seed(matc::kHeldOutPolygonSeed, ndotv, roughness), 8, 1);
    for (std::size_t q = 0; q < quads.size(); ++q) {
      const auto& vertices = quads[q].vertices;
      const Rgb reference =
          matc::integrate_polygon_light(
              lobe, vertices, [&](double mu) { return exact.at(mu); }, inputs.samples)
              .mean;
      const double lobe_share =
          matc::integrate_polygon_light(lobe, vertices, one, inputs.samples).mean[0];
      const matc::runtime::LtcFollowing g =
          matc::runtime::ltc_following(inverse, ndotv, roughness, albedo, vertices);
      const Rgb at_light = matc::runtime::evaluate_fresnel(compiled.coefficients, basis, g.vdoth);
      const Rgb quality_radiance = matc::runtime::polygon_light_ltc_following(
          compiled.coefficients, lut, basis, ltc, ndotv, roughness, vertices);
      const Rgb one_shape = matc::runtime::polygon_light_ltc(compiled.coefficients, lut, ltc, ndotv,
                                                             roughness, vertices);
      Sums& s = sums[band][q % 2];
      const double i = g.integral;
      const auto shaped = [&](double w) { return i * (g.ratio + w * (1.0 - g.ratio)); };
      for (std::size_t c = 0; c < 3; ++c) {
        // The quality level's Fresnel, F at the light blended with the lobe's average by w.
        const auto fresnel = [&](double w) {
          return (1.0 - w) * albedo * at_light[c] + w * fbar[c];
        };
        std::array<double, kEstimates> estimate{};
        estimate[schlick] = i * (compiled.f0[c] * lobes[0] + (1.0 - compiled.f0[c]) * lobes[1]);
        estimate[ours] = one_shape[c];
        estimate[quality] = quality_radiance[c];
        estimate[one_shape_exact_fbar] = i * fbar_exact[c];
        estimate[lobe_exact_fbar] = lobe_share * fbar_exact[c] / albedo;
        estimate[quality_shape_exact_fbar] = g.shaped * fbar_exact[c];
        estimate[lobe_quality_fresnel] = lobe_share * fresnel(i) / albedo;
        for (std::size_t k = 0; k < kEstimates; ++k) {
          const double e = std::abs(estimate[k] - reference[c]);
          s.error[k][c] += e;
          if (reference[c] > kLitThreshold) s.relative[k][c] += e / reference[c];
        }
        for (std::size_t k = 0; k < kFresnelWeights.size(); ++k) {
          s.fresnel_weight_error[k][c] +=
              std::abs(g.shaped * fresnel(kFresnelWeights[k].of(i, g.extent)) - reference[c]);
        }
        for (std::size_t k = 0; k < kShapeWeights.size(); ++k) {
          s.shape_weight_error[k][c] +=
              std::abs(shaped(kShapeWeights[k].of(i, g.extent)) * fresnel(i) - reference[c]);
        }
        s.reference[c] += reference[c];
        if (reference[c] > kLitThreshold) ++s.lit[c];
      }
      ++s.lights;
    }
  }
  return sums;
}

std::string channels(const Rgb& sum, const Rgb& over) {
  return fmt::format("{:.1f} / {:.1f} / {:.1f}", 100.0 * sum[0] / over[0], 100.0 * sum[1] / over[1],
                     100.0 * sum[2] / over[2]);
}

Rgb counts(const std::array<std::size_t, 3>& lit) {
  return {static_cast<double>(std::max<std::size_t>(lit[0], 1)),
          static_cast<double>(std::max<std::size_t>(lit[1], 1)),
          static_cast<double>(std::max<std::size_t>(lit[2], 1))};
}

void print_table(const std::vector<std::string>& names, const std::vector<MaterialSums>& results,
                 const std::function<Sums(const MaterialSums&)>& select, bool per_light) {
  std::string header = "| material | lights |";
  std::string rule = "|---|---:|";
  for (const char* name : kEstimateNames) {
    header += fmt::format(" {} |", name);
    rule += "---:|";
  }
  fmt::print("{}\n{}\n", header, rule);
  for (std::size_t m = 0; m < names.size(); ++m) {
    const Sums s = select(results[m]);
    std::string row = fmt::format("| {} | {} |", names[m], s.lights);
    for (std::size_t k = 0; k < kEstimates; ++k) {
      row += fmt::format(" {} |", per_light ? channels(s.relative[k], counts(s.lit))
                                            : channels(s.error[k], s.reference));
    }
    fmt::print("{}\n", row);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Area lights: the quality level (shape and Fresnel following the light) on random quads"};
  std::vector<std::string> files;
  std::size_t views = 200, samples = std::size_t{1} << 15;
  bool compare_weights = false;
  app.add_option("files", files, "Material files (.json)")->required();
  app.add_option("--views", views, "Random (NdotV, roughness) views; 8 quads each")
      ->capture_default_str();
  app.add_option("--samples", samples, "Reference sample pairs per quad")->capture_default_str();
  app.add_flag("--compare-weights", compare_weights,
               "Also score the quality level's blend with other weights");
  CLI11_PARSE(app, argc, argv);

  const matc::Build build(matc::one_basis_build());
  const matc::ComparisonLobes lobes(build.basis().samples());
  const matc::Lut schlick_lut = matc::preintegrate_lut(lobes.view(), {});
  const Inputs inputs{build, schlick_lut, views, samples};
  std::vector<std::string> names;
  std::vector<std::future<MaterialSums>> futures;
  for (const std::string& file : files) {
    const matc::ParseResult parsed = matc::read_material_file(file);
    if (!parsed.material) {
      fmt::print(stderr, "matc_area_light_quality_study: cannot read {}\n", file);
      return 1;
    }
    names.push_back(parsed.material->name);
    futures.push_back(std::async(std::launch::async, [&inputs, material = *parsed.material] {
      return study_material(inputs, material);
    }));
  }
  std::vector<MaterialSums> results;
  for (auto& future : futures)
    results.push_back(future.get());

  const auto set = [](std::size_t which) {
    return [which](const MaterialSums& m) {
      Sums s;
      for (const auto& band : m)
        s.add(band[which]);
      return s;
    };
  };
  const auto all = [](const MaterialSums& m) {
    Sums s;
    for (const auto& band : m)
      for (const Sums& lights : band)
        s.add(lights);
    return s;
  };
  fmt::print(
      "{} random views (NdotV 0.05-1, roughness {}-{}), 8 quads each (lobe_polygons.h, seeded "
      "apart from the fit's), against the exact integral ({} sample pairs each). Radiance-weighted "
      "error, sum |L - ref| / sum ref, in percent, R / G / B.\n\nQuads centred where the lobe "
      "reflects:\n\n",
      views, kLowestRoughness, kHighestRoughness, samples);
  print_table(names, results, set(0), false);
  fmt::print("\nQuads anywhere (centres down to 17 degrees below the horizon):\n\n");
  print_table(names, results, set(1), false);
  fmt::print("\nAll quads:\n\n");
  print_table(names, results, all, false);
  fmt::print(
      "\nPer light: the mean of |L - ref| / ref over the quads with ref > {} in that channel "
      "(both sets), in percent:\n\n",
      kLitThreshold);
  print_table(names, results, all, true);
  fmt::print("\nPer roughness band, all quads, radiance-weighted, R / G / B:\n\n");
  fmt::print(
      "| material | roughness | lights | LTC x Schlick's | LTC x ours (one shape) | quality "
      "level |\n|---|---|---:|---:|---:|---:|\n");
  for (std::size_t m = 0; m < names.size(); ++m) {
    for (std::size_t b = 0; b < kBands.size(); ++b) {
      Sums s;
      for (const Sums& lights : results[m][b])
        s.add(lights);
      fmt::print("| {} | {:.2f}-{:.2f} | {} | {} | {} | {} |\n", names[m], kBands[b][0],
                 kBands[b][1], s.lights, channels(s.error[schlick], s.reference),
                 channels(s.error[ours], s.reference), channels(s.error[quality], s.reference));
    }
  }
  if (compare_weights) {
    const auto print_weights = [&](const char* title, const auto& weights, auto member) {
      fmt::print("\n{}\n\n| material |", title);
      for (const Weight& w : weights)
        fmt::print(" w = {} |", w.name);
      fmt::print("\n|---|");
      for (std::size_t k = 0; k < weights.size(); ++k)
        fmt::print("---:|");
      fmt::print("\n");
      for (std::size_t m = 0; m < names.size(); ++m) {
        const Sums s = all(results[m]);
        std::string row = fmt::format("| {} |", names[m]);
        for (std::size_t k = 0; k < weights.size(); ++k)
          row += fmt::format(" {} |", channels((s.*member)[k], s.reference));
        fmt::print("{}\n", row);
      }
    };
    print_weights(
        "The quality level with other weights w for its Fresnel, I' ((1 - w) E F(light) + w "
        "Fbar), all quads, radiance-weighted, R / G / B:",
        kFresnelWeights, &Sums::fresnel_weight_error);
    print_weights(
        "The quality level with other weights w for its shape, I (r + w (1 - r)), all quads, "
        "radiance-weighted, R / G / B:",
        kShapeWeights, &Sums::shape_weight_error);
  }
  return 0;
}
