// What a shader needs for a filmed metal's image light (issue #67, docs/accuracy.md "A film's
// image light"). The split sum's Fresnel factor, Fbar(NdotV, roughness), of the exact film curve
// (a Monte-Carlo split sum, matc's reference estimator) against
//   - the 4-term basis' fit of the curve, preintegrated (what matc ships for a film today, before
//     the table of its own), and
//   - a table of Fbar per material over (sqrt(NdotV), roughness), baked from the direct light's
//     64-node F table (docs/accuracy.md "A film's curve as a table") and read bilinearly, at
//     several sizes (nodes over sqrt(NdotV) x nodes over roughness).
// Each cell is the worst |Fbar - reference| over titanium, gold, copper, iron and chromium, the
// channels, and 48 x 13 points of NdotV in [0.05, 1] and roughness in [0.05, 1] (off the tables'
// nodes). The filmed curves are tabulated at 4096 cosines once (lut/split_sum_reference.h); every
// split sum takes 8192 Hammersley samples of the visible normals, the same for every curve.
//   build/bench/matc_thin_film_image_light_study   (about a minute on 2 cores;
//   bench/accuracy/update-docs.sh)
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "fit/coefficients.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/shipped_bases.h"
#include "optics/presets.h"
#include "optics/spectral.h"
#include "optics/thin_film.h"

namespace {

constexpr std::size_t kSamples = 8192;
constexpr std::array<std::string_view, 5> kMetals = {"Ti", "Au", "Cu", "Fe", "Cr"};
constexpr std::array<double, 4> kIndices = {1.2, 1.5, 2.0, 2.5};
struct Band {
  std::string_view name;
  std::vector<double> thicknesses;
};
const std::array<Band, 3> kBands = {{{"0-100 nm", {0.0, 50.0, 100.0}},
                                     {"200-350 nm", {200.0, 350.0}},
                                     {"500-1000 nm", {500.0, 750.0, 1000.0}}}};

// Table nodes: 2^k + 1 over u = sqrt(NdotV) and over roughness in [0.05, 1], so that every
// layout's nodes are among the finest grid's (65 x 17) of its roughness spacing: uniform in the
// perceptual roughness, as matc's table is, or uniform in sqrt(roughness - 0.05), denser towards
// a mirror, where the lobe's average of F leaves F(NdotV) fastest.
constexpr std::size_t kFinestU = 65;
constexpr std::size_t kFinestRoughness = 17;
constexpr double kMinRoughness = 0.05;
enum class Spacing { uniform, sqrt };
constexpr std::array<Spacing, 2> kSpacings = {Spacing::uniform, Spacing::sqrt};
double node_u(std::size_t i, std::size_t nodes) {
  return static_cast<double>(i) / static_cast<double>(nodes - 1);
}
// Roughness from the axis' coordinate t in [0, 1], and back.
double roughness_at(Spacing spacing, double t) {
  return kMinRoughness + (1.0 - kMinRoughness) * (spacing == Spacing::sqrt ? t * t : t);
}
double roughness_coordinate(Spacing spacing, double roughness) {
  const double t = (roughness - kMinRoughness) / (1.0 - kMinRoughness);
  return spacing == Spacing::sqrt ? std::sqrt(t) : t;
}

struct Layout {
  std::size_t u_nodes;
  std::size_t roughness_nodes;
  Spacing spacing;
  bool over_albedo;  // the table holds Fbar / E, and the shader multiplies by E
  std::string_view name;
};
constexpr std::array<Layout, 7> kLayouts = {{
    {65, 17, Spacing::uniform, false, "Fbar, 65 x 17"},
    {65, 17, Spacing::uniform, true, "Fbar / E, 65 x 17"},
    {65, 17, Spacing::sqrt, false, "Fbar, 65 x 17 sqrt"},
    {33, 9, Spacing::sqrt, true, "Fbar / E, 33 x 9 sqrt"},
    {65, 9, Spacing::sqrt, true, "Fbar / E, 65 x 9 sqrt"},
    {33, 17, Spacing::sqrt, true, "Fbar / E, 33 x 17 sqrt"},
    {65, 17, Spacing::sqrt, true, "Fbar / E, 65 x 17 sqrt"},
}};

// The check points: off every layout's nodes.
constexpr std::size_t kCheckU = 48;
constexpr std::size_t kCheckRoughness = 13;
double check_ndotv(std::size_t i) {
  const double u = std::sqrt(0.05) + (1.0 - std::sqrt(0.05)) * (static_cast<double>(i) + 0.37) /
                                         static_cast<double>(kCheckU);
  return u * u;
}
double check_roughness(std::size_t j) {
  return kMinRoughness + (1.0 - kMinRoughness) * (static_cast<double>(j) + 0.41) /
                             static_cast<double>(kCheckRoughness);
}

// The direct light's table: F at 64 nodes uniform in sqrt(mu), read linearly.
class CosineTable final : public matc::ReflectanceCurve {
 public:
  explicit CosineTable(const matc::ReflectanceCurve& curve) {
    for (std::size_t i = 0; i < kNodes; ++i) {
      const double u = static_cast<double>(i) / (kNodes - 1);
      values_[i] = curve.at(u * u);
    }
  }
  matc::Rgb at(double mu) const override {
    const double x = std::sqrt(std::clamp(mu, 0.0, 1.0)) * (kNodes - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), kNodes - 2);
    const double w = x - static_cast<double>(i);
    matc::Rgb out{};
    for (std::size_t c = 0; c < 3; ++c)
      out[c] = (1.0 - w) * values_[i][c] + w * values_[i + 1][c];
    return out;
  }

 private:
  static constexpr std::size_t kNodes = 64;
  std::array<matc::Rgb, kNodes> values_{};
};

// The 4-term fit, as the shaders evaluate it.
class FittedCurve final : public matc::ReflectanceCurve {
 public:
  explicit FittedCurve(const matc::ReflectanceCurve& curve)
      : coefficients_(matc::solve_coefficients(curve, matc::runtime::shipped_basis())) {}
  matc::Rgb at(double mu) const override {
    return matc::runtime::evaluate_fresnel(coefficients_, matc::runtime::shipped_shader_basis(),
                                           mu);
  }

 private:
  matc::runtime::Coefficients coefficients_;
};

// 1 at every cosine: its split sum is the lobe's directional albedo E(NdotV, roughness), b_0's
// entry of matc's table.
class One final : public matc::ReflectanceCurve {
 public:
  matc::Rgb at(double) const override { return {1.0, 1.0, 1.0}; }
};

struct Estimators {
  // Per spacing: kFinestU x kFinestRoughness, u fastest.
  std::array<std::vector<matc::SplitSumEstimator>, kSpacings.size()> nodes;
  std::vector<matc::SplitSumEstimator> checks;  // kCheckU x kCheckRoughness, NdotV fastest
};

const Estimators& estimators() {
  static const Estimators all = [] {
    Estimators e;
    for (std::size_t s = 0; s < kSpacings.size(); ++s) {
      for (std::size_t j = 0; j < kFinestRoughness; ++j) {
        const double t = static_cast<double>(j) / static_cast<double>(kFinestRoughness - 1);
        for (std::size_t i = 0; i < kFinestU; ++i) {
          const double u = node_u(i, kFinestU);
          e.nodes[s].emplace_back(std::max(u * u, 1e-4), roughness_at(kSpacings[s], t), kSamples);
        }
      }
    }
    for (std::size_t j = 0; j < kCheckRoughness; ++j)
      for (std::size_t i = 0; i < kCheckU; ++i)
        e.checks.emplace_back(check_ndotv(i), check_roughness(j), kSamples);
    return e;
  }();
  return all;
}

// A layout's table, from its spacing's finest node grid, read bilinearly at (NdotV, roughness).
matc::Rgb read_table(const std::vector<matc::Rgb>& finest, const Layout& layout, double ndotv,
                     double roughness) {
  const std::size_t u_stride = (kFinestU - 1) / (layout.u_nodes - 1);
  const std::size_t r_stride = (kFinestRoughness - 1) / (layout.roughness_nodes - 1);
  const double x = std::sqrt(ndotv) * static_cast<double>(layout.u_nodes - 1);
  const double y = roughness_coordinate(layout.spacing, roughness) *
                   static_cast<double>(layout.roughness_nodes - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(x), layout.u_nodes - 2);
  const std::size_t j = std::min(static_cast<std::size_t>(y), layout.roughness_nodes - 2);
  const double wx = x - static_cast<double>(i), wy = y - static_cast<double>(j);
  const auto at = [&](std::size_t a, std::size_t b) {
    return finest[(b * r_stride) * kFinestU + a * u_stride];
  };
  matc::Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) {
    out[c] = (1 - wy) * ((1 - wx) * at(i, j)[c] + wx * at(i + 1, j)[c]) +
             wy * ((1 - wx) * at(i, j + 1)[c] + wx * at(i + 1, j + 1)[c]);
  }
  return out;
}

// Worst error of the 4-term fit and of each layout, over the metals, for films of `index` in
// `band`.
using Row = std::array<double, 1 + kLayouts.size()>;
Row measure(double index, const Band& band) {
  const Estimators& e = estimators();
  Row worst{};
  for (const std::string_view symbol : kMetals) {
    const matc::Spectrum& metal = matc::preset_spectrum(*matc::find_metal_preset(symbol));
    for (const double thickness : band.thicknesses) {
      const matc::ThinFilmCurve exact(metal, {index, thickness});
      const matc::TabulatedCurve curve(exact);
      const FittedCurve fitted(curve);
      const CosineTable table(curve);
      // Per spacing, the nodes' Fbar of the direct light's table, and Fbar / E (the lobe's
      // average of F, which the shader multiplies by E, the entry of matc's table it fetches
      // anyway).
      std::array<std::array<std::vector<matc::Rgb>, 2>, kSpacings.size()> finest;
      for (std::size_t s = 0; s < kSpacings.size(); ++s) {
        for (const matc::SplitSumEstimator& node : e.nodes[s]) {
          const matc::Rgb fbar = node.integrate(table);
          const double albedo = node.integrate(One{})[0];
          matc::Rgb average{};
          for (std::size_t c = 0; c < 3; ++c)
            average[c] = albedo > 0.0 ? fbar[c] / albedo : 0.0;
          finest[s][0].push_back(fbar);
          finest[s][1].push_back(average);
        }
      }
      for (std::size_t j = 0; j < kCheckRoughness; ++j) {
        for (std::size_t i = 0; i < kCheckU; ++i) {
          const matc::SplitSumEstimator& check = e.checks[j * kCheckU + i];
          const matc::Rgb reference = check.integrate(curve);
          const matc::Rgb four_terms = check.integrate(fitted);
          const double albedo = check.integrate(One{})[0];
          for (std::size_t c = 0; c < 3; ++c)
            worst[0] = std::max(worst[0], std::abs(four_terms[c] - reference[c]));
          for (std::size_t l = 0; l < kLayouts.size(); ++l) {
            const Layout& layout = kLayouts[l];
            const auto s = static_cast<std::size_t>(layout.spacing == Spacing::sqrt);
            const matc::Rgb read = read_table(finest[s][layout.over_albedo ? 1 : 0], layout,
                                              check_ndotv(i), check_roughness(j));
            const double scale = layout.over_albedo ? albedo : 1.0;
            for (std::size_t c = 0; c < 3; ++c)
              worst[1 + l] = std::max(worst[1 + l], std::abs(scale * read[c] - reference[c]));
          }
        }
      }
    }
  }
  return worst;
}

}  // namespace

int main() {
  estimators();  // once, before the threads share them
  std::vector<std::future<Row>> rows;
  for (const double index : kIndices)
    for (const Band& band : kBands)
      rows.push_back(std::async(std::launch::async, measure, index, std::cref(band)));
  fmt::print("| film index | thickness | the 4-term fit, preintegrated |");
  for (const Layout& layout : kLayouts)
    fmt::print(" {} |", layout.name);
  fmt::print("\n|---:|---|---:|");
  for (std::size_t l = 0; l < kLayouts.size(); ++l)
    fmt::print("---:|");
  fmt::print("\n");
  std::size_t next = 0;
  for (const double index : kIndices) {
    for (const Band& band : kBands) {
      fmt::print("| {:.1f} | {} |", index, band.name);
      for (const double error : rows[next].get())
        fmt::print(" {:.4f} |", error);
      ++next;
      fmt::print("\n");
    }
  }
  fmt::print(
      "\nA table's memory per material, RGBA16F: 33 x 9: {:.1f} KiB; 65 x 9: {:.1f} KiB; "
      "33 x 17: {:.1f} KiB; 65 x 17: {:.1f} KiB.\n",
      33 * 9 * 8 / 1024.0, 65 * 9 * 8 / 1024.0, 33 * 17 * 8 / 1024.0, 65 * 17 * 8 / 1024.0);
  return 0;
}
