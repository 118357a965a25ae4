// The area-light study of docs/ltc.md: how well the LTC table fits GGX (per roughness band, the
// L1 distance and the polygon-light error of each texel), and LTC with ours, with Schlick's and
// with the exact preintegrated Fresnel against the exact integral over a grid of views,
// roughnesses and quad lights, for every material given. With --compare-objectives it also fits
// a table with Heitz et al.'s objective (cubed differences) in-process and shows both fits.
//   matc_area_light_study [--samples N] [--compare-objectives] FILES...
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "matc/compile.h"
#include "matc/emit/build.h"
#include "matc/ltc/area_light_reference.h"
#include "matc/ltc/ltc_fit.h"
#include "matc/ltc/polygon_light.h"
#include "matc/lut/comparison_lobes.h"
#include "matc/lut/split_sum_reference.h"
#include "matc/material/parse.h"
#include "matc/runtime/ltc.h"

namespace {

using matc::facing_square;
using matc::Vec3;

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

// Per roughness band: the mean and largest L1 distance and polygon error of the table's texels.
void print_fit_quality(const char* label, const matc::runtime::LtcTableView& table,
                       std::size_t samples) {
  const std::vector<double> polygon = matc::ltc_polygon_errors(table, samples);
  constexpr std::array<std::array<double, 2>, 4> kBands = {
      {{0.0, 0.25}, {0.25, 0.5}, {0.5, 0.75}, {0.75, 1.0001}}};
  for (const auto& [low, high] : kBands) {
    double l1_sum = 0, l1_max = 0, polygon_sum = 0, polygon_max = 0, grazing_l1 = 0;
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
        if (ndotv < 0.1) {
          grazing_l1 += l1;
          ++grazing;
          continue;
        }
        l1_sum += l1;
        l1_max = std::max(l1_max, l1);
        polygon_sum += error;
        polygon_max = std::max(polygon_max, error);
        ++count;
      }
    }
    fmt::print("| {} | {:.2f}-{:.2f} | {:.3f} | {:.3f} | {:.4f} | {:.4f} | {:.3f} |\n", label, low,
               std::min(high, 1.0), l1_sum / static_cast<double>(count), l1_max,
               polygon_sum / static_cast<double>(count), polygon_max,
               grazing_l1 / static_cast<double>(std::max<std::size_t>(grazing, 1)));
  }
}

void print_grid(const std::vector<matc::CompiledMaterial>& materials, const matc::Lut& lut,
                const matc::Lut& lobe_lut, const matc::runtime::LtcTableView& ltc,
                std::size_t samples, bool fresnel_columns) {
  std::vector<std::future<Sums>> results;
  for (const matc::CompiledMaterial& compiled : materials) {
    results.push_back(std::async(std::launch::async, [&, samples] {
      return study_material(compiled, lut, lobe_lut, ltc, samples);
    }));
  }
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const Sums s = results[m].get();
    const double n = static_cast<double>(s.count);
    const auto relative = [&](double sum) { return 100.0 * sum / s.reference; };
    if (fresnel_columns) {
      fmt::print("| {} | {:.5f} | {:.5f} | {:.3f} | {:.2f}% | {:.2f}% | {:.2f}% | {} |\n",
                 materials[m].material.name, s.schlick_fresnel / n, s.ours_fresnel / n,
                 s.ours_fresnel / s.schlick_fresnel, relative(s.schlick), relative(s.ours),
                 relative(s.ltc_exact), s.ours <= s.schlick ? "yes" : "no");
    } else {
      fmt::print("| {} | {:.2f}% |\n", materials[m].material.name, relative(s.ltc_exact));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Area lights: the LTC fit's quality and LTC with ours/Schlick's on a grid"};
  std::vector<std::string> files;
  std::size_t samples = 1u << 14;
  bool compare = false;
  app.add_option("files", files, "Material files (.json)")->required();
  app.add_option("--samples", samples, "Reference sample pairs per light")->capture_default_str();
  app.add_flag("--compare-objectives", compare,
               "Also fit a table with Heitz et al.'s objective and compare the two");
  CLI11_PARSE(app, argc, argv);

  const matc::Build build(matc::BuildOptions{});
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
  matc::LtcTable heitz;
  if (compare) heitz = matc::fit_ltc_table({shipped.size, 0, matc::LtcObjective::l3});

  fmt::print(
      "The LTC table's fit per roughness band, texels with NdotV >= 0.1 (the grazing columns "
      "apart): the L1 distance between the normalised GGX lobe and the LTC (0 to 2; half of it "
      "bounds the error over any light, relative to the albedo), and the polygon-light error "
      "(the largest of three squares' |E I_ltc - integral of f cos|, relative to the albedo E, "
      "{} reference samples):\n\n"
      "| table | roughness | L1: mean | L1: max | polygon: mean | polygon: max | L1 at NdotV < "
      "0.1: mean |\n|---|---|---:|---:|---:|---:|---:|\n",
      samples);
  print_fit_quality("shipped (L1 objective)", shipped, samples);
  if (compare) print_fit_quality("Heitz et al.'s objective", heitz.view(), samples);

  fmt::print(
      "\nEach material over {} views x {} roughnesses x 4 quad lights (towards the mirror "
      "direction, overhead, to the side, across the horizon), all channels: the Fresnel's share "
      "(mean |L - LTC x exact Fbar|) with Schlick's and ours, and the mean error against the "
      "exact integral ({} sample pairs each) relative to its mean:\n\n"
      "| material | Fresnel share: Schlick's | ours | ours / Schlick's | vs exact: LTC x "
      "Schlick's | LTC x ours | LTC x exact Fbar | ours <= Schlick's |\n"
      "|---|---:|---:|---:|---:|---:|---:|---|\n",
      kNdotV.size(), kRoughness.size(), samples);
  print_grid(materials, build.stored_lut(), lobe_lut, shipped, samples, true);
  if (compare) {
    fmt::print(
        "\nLTC's own error (LTC x exact Fbar against the exact integral, relative) with the table "
        "fitted to Heitz et al.'s objective:\n\n| material | LTC x exact Fbar |\n|---|---:|\n");
    print_grid(materials, build.stored_lut(), lobe_lut, heitz.view(), samples, false);
  }
  return 0;
}
