#include "compile/film_tables.h"

#include <algorithm>
#include <cmath>

#include "lut/microfacet_samples.h"
#include "lut/split_sum_reference.h"

namespace matc {
namespace {

// Linear interpolation coordinates of x in [0, 1] over `nodes` nodes: the lower node and the
// weight of the upper one.
std::pair<std::size_t, double> between_nodes(double x, std::size_t nodes) {
  const double scaled = std::clamp(x, 0.0, 1.0) * static_cast<double>(nodes - 1);
  const std::size_t lower = std::min(static_cast<std::size_t>(scaled), nodes - 2);
  return {lower, scaled - static_cast<double>(lower)};
}

// The roughness axis' coordinate: uniform in sqrt(roughness - 0.05), denser towards a mirror,
// where the lobe's average of F leaves F(NdotV) fastest.
double roughness_coordinate(double roughness) {
  return std::sqrt(std::max(roughness - FilmTables::kMinRoughness, 0.0) /
                   (1.0 - FilmTables::kMinRoughness));
}

// The F table as a curve, what the split sums of its nodes integrate.
class FresnelTableCurve final : public ReflectanceCurve {
 public:
  explicit FresnelTableCurve(const FilmTables& tables) : tables_(tables) {}
  Rgb at(double mu) const override { return tables_.fresnel_at(mu); }

 private:
  const FilmTables& tables_;
};

}  // namespace

double film_table_cosine(std::size_t i) {
  const double u = static_cast<double>(i) / (FilmTables::kCosineNodes - 1);
  return u * u;
}

double film_table_view_cosine(std::size_t i) {
  const double u = static_cast<double>(i) / (FilmTables::kViewNodes - 1);
  return u * u;
}

double film_table_roughness(std::size_t j) {
  const double t = static_cast<double>(j) / (FilmTables::kRoughnessNodes - 1);
  return FilmTables::kMinRoughness + (1.0 - FilmTables::kMinRoughness) * t * t;
}

Rgb FilmTables::fresnel_at(double mu) const {
  const auto [i, w] = between_nodes(std::sqrt(std::clamp(mu, 0.0, 1.0)), kCosineNodes);
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c)
    out[c] = (1.0 - w) * fresnel[i][c] + w * fresnel[i + 1][c];
  return out;
}

Rgb FilmTables::preintegrated_at(double ndotv, double roughness) const {
  const auto [i, wx] = between_nodes(std::sqrt(std::clamp(ndotv, 0.0, 1.0)), kViewNodes);
  const auto [j, wy] = between_nodes(roughness_coordinate(roughness), kRoughnessNodes);
  const auto at = [&](std::size_t x, std::size_t y) -> const Rgb& {
    return preintegrated[y * kViewNodes + x];
  };
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) {
    out[c] = (1.0 - wy) * ((1.0 - wx) * at(i, j)[c] + wx * at(i + 1, j)[c]) +
             wy * ((1.0 - wx) * at(i, j + 1)[c] + wx * at(i + 1, j + 1)[c]);
  }
  return out;
}

FilmTables bake_film_tables(const ReflectanceCurve& curve, std::size_t samples) {
  FilmTables tables;
  for (std::size_t i = 0; i < FilmTables::kCosineNodes; ++i)
    tables.fresnel[i] = curve.at(film_table_cosine(i));
  const FresnelTableCurve table(tables);
  const HammersleySet set(samples);
  tables.preintegrated.reserve(FilmTables::kViewNodes * FilmTables::kRoughnessNodes);
  for (std::size_t j = 0; j < FilmTables::kRoughnessNodes; ++j) {
    for (std::size_t i = 0; i < FilmTables::kViewNodes; ++i) {
      const double ndotv = std::max(film_table_view_cosine(i), kMinIntegratedNdotV);
      tables.preintegrated.push_back(
          SplitSumEstimator(set, ndotv, film_table_roughness(j)).integrate(table));
    }
  }
  return tables;
}

}  // namespace matc
