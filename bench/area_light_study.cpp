// The area-light study of docs/ltc.md: how well the LTC table fits GGX (per roughness band, the
// L1 distance and the polygon-light error of each texel), and LTC with ours, with Schlick's and
// with the exact preintegrated Fresnel against the exact integral over a grid of views,
// roughnesses and quad lights, for every material given. Every table is also scored on random
// quad lights none of the fits saw (lobe_polygons.h), per texel and at random views read between
// texels as a shader reads the table. With --compare-objectives it also fits tables to the
// densities' L1 distance (shipped before issue #31), Heitz et al.'s objective (cubed differences)
// and the polygon objective on the preintegrated table's view axis (sqrt(NdotV), shipped before
// the angular axis) and with two variants of the polygon objective (more quads at grazing views,
// a term for the mass below the horizon: ltc_fit.h) in-process and shows them with the shipped
// one.
//   matc_area_light_study [--samples N] [--compare-objectives] FILES...
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "compile/compile.h"
#include "emit/build.h"
#include "ltc/area_light_reference.h"
#include "ltc/lobe_polygons.h"
#include "ltc/ltc_fit.h"
#include "ltc/polygon_light.h"
#include "lut/comparison_lobes.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/ltc.h"
#include "material/parse.h"

namespace {

using matc::facing_square;
using matc::Vec3;

// The polygon objective's variants (ltc_fit.h) the study tries.
constexpr std::size_t kGrazingVariantPolygons = 4 * matc::kLtcTrainingPolygons;
constexpr double kHorizonVariantWeight = 0.1;
constexpr const char* kGrazingVariantLabel = "polygon objective, 4x the quads at NdotV < 0.1";
constexpr const char* kHorizonVariantLabel = "polygon objective + 0.1 x the mass below the horizon";

// The roughness bands both fit tables report (the last one takes roughness 1 in).
constexpr std::array<std::array<double, 2>, 4> kRoughnessBands = {
    {{0.0, 0.25}, {0.25, 0.5}, {0.5, 0.75}, {0.75, 1.0001}}};

constexpr std::array kNdotV = {0.05, 0.15, 0.3, 0.45, 0.6, 0.75, 0.9, 1.0};
constexpr std::array kRoughness = {0.1, 0.25, 0.4, 0.55, 0.7, 0.9};

// The grid's lights for a view cosine: towards the mirror direction (the highlight), overhead,
// to the side, and across the horizon on the reflection side.
std::vector<std::array<Vec3, 4>> lights_for(double ndotv) {
  const double sine = std::sqrt(1.0 - ndotv * ndotv);
  return {facing_square({-sine, 0.0, ndotv}, 2.0, 0.5), facing_square({0.0, 0.0, 1.0}, 2.0, 0.75),
          facing_square({0.0, 1.0, 0.5}, 1.5, 0.5), facing_square({-1.0, 0.0, 0.05}, 2.0, 0.6)};
}

struct Sums {
  double schlick_fresnel = 0, ours_fresnel = 0;                // against LTC x exact Fbar
  double schlick = 0, ours = 0, ltc_exact = 0, reference = 0;  // against the reference
  std::size_t count = 0;
};

Sums study_material(const matc::CompiledMaterial& compiled, const matc::Lut& lut,
                    const matc::Lut& lobe_lut, const matc::runtime::LtcTableView& ltc,
                    std::size_t samples) {
  const auto curve = matc::make_reflectance_curve(compiled.material, compiled.color);
  const matc::TabulatedCurve tabulated(*curve);
  Sums sums;
  for (const double ndotv : kNdotV) {
    for (const double roughness : kRoughness) {
      const matc::Rgb fbar_exact = matc::SplitSumEstimator(ndotv, roughness).integrate(tabulated);
      const auto lobes = matc::runtime::sample_lut(lobe_lut.view(), ndotv, roughness);
      const matc::GgxLobe lobe(ndotv, roughness);
      for (const auto& light : lights_for(ndotv)) {
        const double integral = matc::runtime::ltc_polygon_integral(
            matc::runtime::sample_ltc(ltc, ndotv, roughness), light);
        const matc::Rgb ours = matc::runtime::polygon_light_ltc(compiled.coefficients, lut.view(),
                                                                ltc, ndotv, roughness, light);
        const matc::Rgb reference =
            matc::integrate_polygon_light(
                lobe, light, [&](double mu) { return tabulated.at(mu); }, samples)
                .mean;
        for (std::size_t c = 0; c < 3; ++c) {
          const double schlick =
              integral * (compiled.f0[c] * lobes[0] + (1.0 - compiled.f0[c]) * lobes[1]);
          const double exact = integral * fbar_exact[c];
          sums.schlick_fresnel += std::abs(schlick - exact);
          sums.ours_fresnel += std::abs(ours[c] - exact);
          sums.schlick += std::abs(schlick - reference[c]);
          sums.ours += std::abs(ours[c] - reference[c]);
          sums.ltc_exact += std::abs(exact - reference[c]);
          sums.reference += reference[c];
          ++sums.count;
        }
      }
    }
  }
  return sums;
}

// Per roughness band: the mean and largest L1 distance, polygon error and held-out error of the
// table's texels.
void print_fit_quality(const char* label, const matc::runtime::LtcTableView& table,
                       std::size_t samples, const matc::TexelPolygons& held_out) {
  const std::vector<double> polygon = matc::ltc_polygon_errors(table, samples);
  const std::vector<matc::PolygonSetError> held_out_errors =
      matc::ltc_held_out_errors(table, held_out);
  for (const auto& [low, high] : kRoughnessBands) {
    double l1_sum = 0, l1_max = 0, polygon_sum = 0, polygon_max = 0, grazing_l1 = 0;
    double held_out_sum = 0, held_out_max = 0, grazing_held_out = 0, below_sum = 0, below_max = 0;
    std::size_t count = 0, grazing = 0;
    for (std::size_t y = 0; y < table.size; ++y) {
      const double roughness = matc::ltc_texel_roughness(y, table.size);
      if (roughness < low || roughness >= high) continue;
      for (std::size_t x = 0; x < table.size; ++x) {
        const double ndotv = matc::ltc_texel_ndotv(x, table.size);
        const auto t = table.texel(x, y);
        const double l1 =
            matc::evaluate_ltc_cell({t[0], t[1], t[2], t[3]}, ndotv, roughness).l1_distance;
        const double error = polygon[y * table.size + x];
        const matc::PolygonSetError& held = held_out_errors[y * table.size + x];
        if (ndotv < 0.1) {
          grazing_l1 += l1;
          grazing_held_out += held.mean;
          ++grazing;
          continue;
        }
        held_out_sum += held.mean;
        held_out_max = std::max(held_out_max, held.max);
        const double below = matc::ltc_mass_below_horizon({t[0], t[1], t[2], t[3]});
        below_sum += below;
        below_max = std::max(below_max, below);
        l1_sum += l1;
        l1_max = std::max(l1_max, l1);
        polygon_sum += error;
        polygon_max = std::max(polygon_max, error);
        ++count;
      }
    }
    const double n = static_cast<double>(count);
    const double grazing_n = static_cast<double>(std::max<std::size_t>(grazing, 1));
    fmt::print(
        "| {} | {:.2f}-{:.2f} | {:.3f} | {:.3f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.3f} | "
        "{:.4f} | {:.4f} | {:.4f} |\n",
        label, low, std::min(high, 1.0), l1_sum / n, l1_max, polygon_sum / n, polygon_max,
        held_out_sum / n, held_out_max, grazing_l1 / grazing_n, grazing_held_out / grazing_n,
        below_sum / n, below_max);
  }
}

// Calls visit(i) for every i < count, spread over the hardware threads (each index on one thread,
// so the results do not depend on the thread count).
template <typename Visit>
void for_each_index_in_parallel(std::size_t count, const Visit& visit) {
  std::vector<std::future<void>> work;
  const std::size_t chunks = std::max(1u, std::thread::hardware_concurrency());
  for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
    work.push_back(std::async(std::launch::async, [&, chunk] {
      for (std::size_t i = chunk; i < count; i += chunks)
        visit(i);
    }));
  }
  for (auto& w : work)
    w.get();
}

// The floor: per texel, the LTC fitted to that texel's own held-out quads (their mean error, and
// separately their largest; fit_ltc_to_polygons), from the better of the two tables' texels.
// What no table of this form can beat on those quads, up to the local search.
struct FloorErrors {
  std::vector<double> mean, max;
};

FloorErrors held_out_floor(const matc::runtime::LtcTableView& shipped,
                           const matc::runtime::LtcTableView& l1,
                           const matc::TexelPolygons& held_out) {
  const std::size_t size = shipped.size;
  FloorErrors floor{std::vector<double>(size * size), std::vector<double>(size * size)};
  for_each_index_in_parallel(size * size, [&](std::size_t index) {
    const std::size_t x = index % size, y = index / size;
    const double ndotv = matc::ltc_texel_ndotv(x, size);
    if (ndotv < matc::kLtcGrazingNdotV) return;  // as print_floor
    const double roughness = matc::ltc_texel_roughness(y, size);
    const auto& quads = held_out[index];
    for (const auto aggregate : {matc::PolygonSetAggregate::mean, matc::PolygonSetAggregate::max}) {
      double best = std::numeric_limits<double>::infinity();
      for (const matc::runtime::LtcTableView& table : {shipped, l1}) {
        const auto t = table.texel(x, y);
        const matc::LtcCellFit fit =
            matc::fit_ltc_to_polygons({t[0], t[1], t[2], t[3]}, ndotv, roughness, quads, aggregate);
        const matc::PolygonSetError e = matc::ltc_polygon_set_error(fit.inverse, quads);
        best = std::min(best, aggregate == matc::PolygonSetAggregate::mean ? e.mean : e.max);
      }
      (aggregate == matc::PolygonSetAggregate::mean ? floor.mean : floor.max)[index] = best;
    }
  });
  return floor;
}

// Per roughness band (NdotV >= 0.1, as above): the held-out mean and largest error of the
// shipped table and the L1 fit, half of the L1 fit's (issue #31's target), and the floor.
void print_floor(const matc::runtime::LtcTableView& shipped, const matc::runtime::LtcTableView& l1,
                 const matc::TexelPolygons& held_out, const FloorErrors& floor) {
  const std::vector<matc::PolygonSetError> shipped_errors =
      matc::ltc_held_out_errors(shipped, held_out);
  const std::vector<matc::PolygonSetError> l1_errors = matc::ltc_held_out_errors(l1, held_out);
  for (const auto& [low, high] : kRoughnessBands) {
    double shipped_sum = 0, shipped_max = 0, l1_sum = 0, l1_max = 0, floor_sum = 0, floor_max = 0,
           noise = 0;
    std::size_t count = 0, quads = 0;
    for (std::size_t y = 0; y < shipped.size; ++y) {
      const double roughness = matc::ltc_texel_roughness(y, shipped.size);
      if (roughness < low || roughness >= high) continue;
      for (std::size_t x = 0; x < shipped.size; ++x) {
        if (matc::ltc_texel_ndotv(x, shipped.size) < matc::kLtcGrazingNdotV) continue;
        const std::size_t index = y * shipped.size + x;
        shipped_sum += shipped_errors[index].mean;
        shipped_max = std::max(shipped_max, shipped_errors[index].max);
        l1_sum += l1_errors[index].mean;
        l1_max = std::max(l1_max, l1_errors[index].max);
        floor_sum += floor.mean[index];
        floor_max = std::max(floor_max, floor.max[index]);
        for (const matc::LobePolygon& quad : held_out[index]) {
          noise += quad.share_error;
          ++quads;
        }
        ++count;
      }
    }
    const double n = static_cast<double>(std::max<std::size_t>(count, 1));
    fmt::print(
        "| {:.2f}-{:.2f} | {:.4f} / {:.4f} | {:.4f} / {:.4f} | {:.4f} / {:.4f} | {:.4f} / {:.4f} "
        "| {:.4f} |\n",
        low, std::min(high, 1.0), l1_sum / n, l1_max, 0.5 * l1_sum / n, 0.5 * l1_max,
        shipped_sum / n, shipped_max, floor_sum / n, floor_max,
        noise / static_cast<double>(std::max<std::size_t>(quads, 1)));
  }
}

// Random views, the same for every table: view angles uniform over [0, 90) degrees, roughness
// uniform over [0, 1], with quads drawn like the held-out ones (another seed); each table read as
// a shader reads it, filtered between texels, on its own view axis.
struct ViewQuads {
  double ndotv = 0.0, roughness = 0.0;
  std::vector<matc::LobePolygon> quads;
};

std::vector<ViewQuads> random_views(std::size_t count, std::size_t quads, std::size_t samples) {
  constexpr std::uint64_t kViewSeed = matc::kHeldOutPolygonSeed + 1000;
  std::vector<ViewQuads> views(count);
  for_each_index_in_parallel(count, [&](std::size_t i) {
    // A low-discrepancy pair per view (the R2 sequence), so that every band gets its share.
    const double u1 = std::fmod(0.5 + 0.7548776662466927 * static_cast<double>(i), 1.0);
    const double u2 = std::fmod(0.5 + 0.5698402909980532 * static_cast<double>(i), 1.0);
    ViewQuads& view = views[i];
    view.ndotv = std::cos(0.5 * std::numbers::pi * u1);
    view.roughness = u2;
    const matc::GgxLobe lobe(view.ndotv, view.roughness);
    view.quads = matc::lobe_polygons(lobe, lobe.albedo(matc::kLtcFitSamplesPerAxis),
                                     matc::lobe_polygon_seed(kViewSeed, view.ndotv, view.roughness),
                                     quads, samples);
  });
  return views;
}

void print_view_quality(const char* label, const matc::runtime::LtcTableView& table,
                        const std::vector<ViewQuads>& views) {
  constexpr double kNearNormal = 15.0;  // degrees
  const double near_normal_cosine = std::cos(kNearNormal * std::numbers::pi / 180.0);
  for (const auto& [low, high] : kRoughnessBands) {
    double sum = 0, max = 0, near_sum = 0, near_max = 0, grazing_sum = 0;
    std::size_t count = 0, near = 0, grazing = 0;
    for (const ViewQuads& view : views) {
      if (view.roughness < low || view.roughness >= high) continue;
      const matc::PolygonSetError error = matc::ltc_polygon_set_error(
          matc::runtime::sample_ltc(table, view.ndotv, view.roughness), view.quads);
      if (view.ndotv < 0.1) {
        grazing_sum += error.mean;
        ++grazing;
        continue;
      }
      sum += error.mean;
      max = std::max(max, error.max);
      ++count;
      if (view.ndotv > near_normal_cosine) {
        near_sum += error.mean;
        near_max = std::max(near_max, error.max);
        ++near;
      }
    }
    const auto mean = [](double total, std::size_t n) {
      return total / static_cast<double>(std::max<std::size_t>(n, 1));
    };
    fmt::print("| {} | {:.2f}-{:.2f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} |\n", label, low,
               std::min(high, 1.0), mean(sum, count), max, mean(near_sum, near), near_max,
               mean(grazing_sum, grazing));
  }
}

// The grid for every material with each table: with one table, the Fresnel's share and every
// estimate's error; with several, LTC's own error (LTC x exact Fbar) per table.
void print_grid(const std::vector<matc::CompiledMaterial>& materials, const matc::Lut& lut,
                const matc::Lut& lobe_lut, const std::vector<matc::runtime::LtcTableView>& tables,
                std::size_t samples, bool fresnel_columns) {
  std::vector<std::vector<std::future<Sums>>> results(materials.size());
  for (std::size_t m = 0; m < materials.size(); ++m) {
    for (const matc::runtime::LtcTableView& ltc : tables) {
      results[m].push_back(std::async(std::launch::async, [&, m, ltc, samples] {
        return study_material(materials[m], lut, lobe_lut, ltc, samples);
      }));
    }
  }
  for (std::size_t m = 0; m < materials.size(); ++m) {
    std::string row = fmt::format("| {} |", materials[m].material.name);
    for (auto& result : results[m]) {
      const Sums s = result.get();
      const double n = static_cast<double>(s.count);
      const auto relative = [&](double sum) { return 100.0 * sum / s.reference; };
      if (fresnel_columns) {
        row += fmt::format(
            " {:.5f} | {:.5f} | {:.3f} | {:.2f}% | {:.2f}% | {:.2f}% | {} |", s.schlick_fresnel / n,
            s.ours_fresnel / n, s.ours_fresnel / s.schlick_fresnel, relative(s.schlick),
            relative(s.ours), relative(s.ltc_exact), s.ours <= s.schlick ? "yes" : "no");
      } else {
        row += fmt::format(" {:.2f}% |", relative(s.ltc_exact));
      }
    }
    fmt::print("{}\n", row);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Area lights: the LTC fit's quality and LTC with ours/Schlick's on a grid"};
  std::vector<std::string> files;
  std::size_t samples = 1u << 14;
  bool compare = false;
  std::size_t held_out_count = 32, held_out_samples = 16384;
  app.add_option("files", files, "Material files (.json)")->required();
  app.add_option("--samples", samples, "Reference sample pairs per light")->capture_default_str();
  app.add_flag("--compare-objectives", compare,
               "Also fit tables to the L1 and Heitz et al.'s objectives and on the previous view "
               "axis and compare them");
  app.add_option("--held-out", held_out_count, "Held-out quad lights per texel")
      ->capture_default_str();
  app.add_option("--held-out-samples", held_out_samples, "Reference sample pairs per held-out quad")
      ->capture_default_str();
  std::size_t view_count = 16384, view_quads = 16, view_samples = 4096;
  app.add_option("--views", view_count, "Random views every table is scored at")
      ->capture_default_str();
  app.add_option("--view-quads", view_quads, "Quad lights per random view")->capture_default_str();
  app.add_option("--view-samples", view_samples, "Reference sample pairs per quad of a view")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const matc::Build build(matc::one_basis_build());
  const matc::ComparisonLobes lobes(build.basis().samples());
  const matc::Lut lobe_lut = matc::preintegrate_lut(lobes.view(), {});
  std::vector<matc::CompiledMaterial> materials;
  for (const std::string& file : files) {
    const matc::ParseResult parsed = matc::read_material_file(file);
    if (!parsed.material) {
      fmt::print(stderr, "matc_area_light_study: cannot read {}\n", file);
      return 1;
    }
    materials.push_back(matc::compile_material(*parsed.material, build.basis()));
  }
  const matc::runtime::LtcTableView shipped = matc::runtime::shipped_ltc_table();
  matc::LtcTable l1, heitz, previous_axis, grazing, horizon;
  if (compare) {
    l1 = matc::fit_ltc_table({.size = shipped.size, .objective = matc::LtcObjective::l1});
    heitz = matc::fit_ltc_table({.size = shipped.size, .objective = matc::LtcObjective::l3});
    previous_axis = matc::fit_ltc_table(
        {.size = shipped.size, .view_axis = matc::runtime::LtcViewAxis::sqrt_ndotv});
    grazing = matc::fit_ltc_table(
        {.size = shipped.size, .variant = {.grazing_polygons = kGrazingVariantPolygons}});
    horizon = matc::fit_ltc_table(
        {.size = shipped.size, .variant = {.horizon_weight = kHorizonVariantWeight}});
  }
  const std::vector<ViewQuads> views = random_views(view_count, view_quads, view_samples);
  const matc::TexelPolygons held_out =
      matc::held_out_polygons(shipped.size, held_out_count, held_out_samples);
  double noise = 0;
  std::size_t quads = 0;
  for (const auto& texel : held_out) {
    for (const matc::LobePolygon& polygon : texel) {
      noise += polygon.share_error;
      ++quads;
    }
  }

  fmt::print(
      "The LTC table's fit per roughness band, texels with NdotV >= 0.1 (the grazing columns "
      "apart): the L1 distance between the normalised GGX lobe and the LTC (0 to 2; half of it "
      "bounds the error over any light, relative to the albedo), and the polygon-light error "
      "(the largest of three squares' |E I_ltc - integral of f cos|, relative to the albedo E, "
      "{} reference samples), and the same error over {} random quad lights per texel that no "
      "fit saw (held out: the mean over texels of each texel's mean, and the largest; "
      "references of {} sample pairs, standard error {:.4f} on average), and the LTC's mass below "
      "the horizon (what a light over the whole upper hemisphere misses, relative to the "
      "albedo):\n\n"
      "| table | roughness | L1: mean | L1: max | polygon: mean | polygon: max | held out: mean | "
      "held out: max | L1 at NdotV < 0.1: mean | held out at NdotV < 0.1: mean | below the "
      "horizon: mean | below the horizon: max |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
      samples, held_out_count, held_out_samples,
      noise / static_cast<double>(std::max<std::size_t>(quads, 1)));
  print_fit_quality("shipped (polygon objective)", shipped, samples, held_out);
  if (compare) {
    print_fit_quality("L1 objective", l1.view(), samples, held_out);
    print_fit_quality("Heitz et al.'s objective", heitz.view(), samples, held_out);
    print_fit_quality(kGrazingVariantLabel, grazing.view(), samples, held_out);
    print_fit_quality(kHorizonVariantLabel, horizon.view(), samples, held_out);
  }

  if (compare) {
    const FloorErrors floor = held_out_floor(shipped, l1.view(), held_out);
    fmt::print(
        "\nThe floor of this form on the held-out quads, texels with NdotV >= 0.1: per texel, the "
        "LTC fitted to that texel's own {} held-out quads (their mean error, and separately their "
        "largest; Nelder-Mead from the shipped and the L1 fit's texel, restarted until it stops "
        "improving), which no table of this form beats on them, against the shipped table, the "
        "L1 fit (the former shipped fit) and half of it (the target); mean over texels "
        "of each texel's mean / the largest, and the references' mean standard error, which the "
        "mean includes:\n\n"
        "| roughness | L1 objective | half of it | shipped (polygon objective) | floor | "
        "references' standard error |\n"
        "|---|---:|---:|---:|---:|---:|\n",
        held_out_count);
    print_floor(shipped, l1.view(), held_out, floor);
  }

  fmt::print(
      "\nWhat a renderer sees: the same error at {} views drawn once for every table (view angle "
      "uniform over 0-90 degrees, roughness over 0-1), {} quads each like the held-out ones "
      "({} sample pairs each), each table filtered between texels as a shader reads it. Mean "
      "over the views with NdotV >= 0.1 of each view's mean, and the largest; then the same over "
      "the views within {} degrees of the normal (a subset), and the mean over the views with "
      "NdotV < 0.1 (not in the first):\n\n"
      "| table | roughness | mean | max | within 15 degrees of the normal: mean | max | "
      "NdotV < 0.1: mean |\n"
      "|---|---|---:|---:|---:|---:|---:|\n",
      view_count, view_quads, view_samples, 15);
  print_view_quality("shipped (polygon objective)", shipped, views);
  if (compare) {
    print_view_quality("polygon objective, columns sqrt(NdotV) (shipped before)",
                       previous_axis.view(), views);
    print_view_quality("L1 objective", l1.view(), views);
    print_view_quality("Heitz et al.'s objective", heitz.view(), views);
    print_view_quality(kGrazingVariantLabel, grazing.view(), views);
    print_view_quality(kHorizonVariantLabel, horizon.view(), views);
  }

  fmt::print(
      "\nEach material over {} views x {} roughnesses x 4 quad lights (towards the mirror "
      "direction, overhead, to the side, across the horizon), all channels: the Fresnel's share "
      "(mean |L - LTC x exact Fbar|) with Schlick's and ours, and the mean error against the "
      "exact integral ({} sample pairs each) relative to its mean:\n\n"
      "| material | Fresnel share: Schlick's | ours | ours / Schlick's | vs exact: LTC x "
      "Schlick's | LTC x ours | LTC x exact Fbar | ours <= Schlick's |\n"
      "|---|---:|---:|---:|---:|---:|---:|---|\n",
      kNdotV.size(), kRoughness.size(), samples);
  print_grid(materials, build.stored_lut(), lobe_lut, {shipped}, samples, true);
  if (compare) {
    fmt::print(
        "\nLTC's own error (LTC x exact Fbar against the exact integral, relative) with each "
        "table:\n\n| material | shipped (polygon objective) | polygon objective, columns "
        "sqrt(NdotV) | L1 objective | Heitz et al.'s objective |\n"
        "|---|---:|---:|---:|---:|\n");
    print_grid(materials, build.stored_lut(), lobe_lut,
               {shipped, previous_axis.view(), l1.view(), heitz.view()}, samples, false);
  }
  return 0;
}
