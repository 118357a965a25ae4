#include "compile/film_tables.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "base/parallel_rows.h"
#include "lut/microfacet_samples.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/coat.h"
#include "optics/coat.h"

namespace matc {
namespace {

// The view cosine the split sums integrate at node i.
double integrated_view_cosine(std::size_t i) {
  return std::max(runtime::film_table_view_cosine(i), kMinIntegratedNdotV);
}

// The split sum of an F row read as the shaders read it is linear in the row's nodes: at each Fbar
// node, a weight per F node (the samples' estimator weights spread over the two nodes each V.H
// falls between). Found once, it preintegrates any number of rows (a thickness stack's slices) at
// a matrix product each.
class FilmSplitSums {
 public:
  explicit FilmSplitSums(std::size_t samples) {
    using runtime::FilmTable;
    const HammersleySet set(samples);
    constexpr std::size_t kNodes = FilmTable::kViewNodes * FilmTable::kRoughnessNodes;
    weights_.assign(kNodes * FilmTable::kCosineNodes, 0.0);
    std::vector<float> vdoth(set.size());
    std::vector<float> weight(set.size());
    for (std::size_t node = 0; node < kNodes; ++node) {
      const std::size_t i = node % FilmTable::kViewNodes;
      const std::size_t j = node / FilmTable::kViewNodes;
      sample_microfacet_reflections(set, integrated_view_cosine(i),
                                    runtime::film_table_roughness(j), vdoth.data(), weight.data());
      double* row = &weights_[node * FilmTable::kCosineNodes];
      for (std::size_t k = 0; k < set.size(); ++k) {
        if (weight[k] <= 0.0f) continue;
        const runtime::FilmNodePosition at = runtime::film_cosine_position(vdoth[k]);
        const double w = static_cast<double>(weight[k]) / static_cast<double>(set.size());
        row[at.left] += w * (1.0 - at.weight);
        row[at.left + 1] += w * at.weight;
      }
    }
  }

  // Fbar at every node (NdotV fastest) of the F row `fresnel`.
  std::vector<Rgb> preintegrate(const FilmFresnelRow& fresnel) const {
    using runtime::FilmTable;
    std::vector<Rgb> out(weights_.size() / FilmTable::kCosineNodes);
    for (std::size_t node = 0; node < out.size(); ++node) {
      const double* row = &weights_[node * FilmTable::kCosineNodes];
      Rgb sum{};
      for (std::size_t m = 0; m < FilmTable::kCosineNodes; ++m) {
        for (std::size_t c = 0; c < 3; ++c)
          sum[c] += row[m] * fresnel[m][c];
      }
      out[node] = sum;
    }
    return out;
  }

 private:
  std::vector<double> weights_;  // node-major, kCosineNodes a node
};

// The weights of `samples` points: those of the default count are found once per process.
std::shared_ptr<const FilmSplitSums> film_split_sums(std::size_t samples) {
  if (samples != kFilmTableSamples) return std::make_shared<const FilmSplitSums>(samples);
  static const auto shared = std::make_shared<const FilmSplitSums>(kFilmTableSamples);
  return shared;
}

runtime::FilmTable fresnel_row(const ReflectanceCurve& curve) {
  runtime::FilmTable table;
  for (std::size_t i = 0; i < runtime::FilmTable::kCosineNodes; ++i)
    table.fresnel[i] = curve.at(runtime::film_table_cosine(i));
  return table;
}

// The largest |mean of the rows either side - the midpoint's row| over the cosine nodes from 0.05.
double midpoint_error(const std::vector<FilmFresnelRow>& nodes,
                      const std::vector<FilmFresnelRow>& mids) {
  double worst = 0.0;
  for (std::size_t s = 0; s < mids.size(); ++s) {
    for (std::size_t i = 0; i < runtime::FilmTable::kCosineNodes; ++i) {
      if (runtime::film_table_cosine(i) < 0.05) continue;
      for (std::size_t c = 0; c < 3; ++c) {
        const double between = 0.5 * (nodes[s][i][c] + nodes[s + 1][i][c]);
        worst = std::max(worst, std::abs(between - mids[s][i][c]));
      }
    }
  }
  return worst;
}

}  // namespace

FilmRows film_rows_by_sweep(const ThinFilmSweep& sweep) {
  return [&sweep](double start_nm, double step_nm, std::size_t count) {
    std::vector<FilmFresnelRow> rows(count);
    fill_rows_in_parallel(runtime::FilmTable::kCosineNodes, 0, [&] {
      return [&, column = std::vector<Rgb>(count)](std::size_t i) mutable {
        sweep.sweep_thickness(runtime::film_table_cosine(i), start_nm, step_nm, column);
        for (std::size_t k = 0; k < count; ++k)
          rows[k][i] = column[k];
      };
    });
    return rows;
  };
}

FilmRows film_rows_by_curve(std::function<std::unique_ptr<ReflectanceCurve>(double)> film_at) {
  return [film_at = std::move(film_at)](double start_nm, double step_nm, std::size_t count) {
    std::vector<FilmFresnelRow> rows(count);
    fill_rows_in_parallel(count, 0, [&] {
      return [&](std::size_t k) {
        rows[k] = fresnel_row(*film_at(start_nm + step_nm * static_cast<double>(k))).fresnel;
      };
    });
    return rows;
  };
}

BakedFilmStack bake_film_stack(const FilmRows& rows_at, double minimum_nm, double maximum_nm,
                               std::size_t samples) {
  const double span = maximum_nm - minimum_nm;
  std::size_t slices = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::ceil(span / kFilmStackFirstSpacingNm)) + 1, 2,
      kMaxFilmStackSlices);
  const auto spacing = [&] { return span / static_cast<double>(slices - 1); };
  std::vector<FilmFresnelRow> nodes = rows_at(minimum_nm, spacing(), slices);
  BakedFilmStack baked;
  for (;;) {
    std::vector<FilmFresnelRow> mids = rows_at(minimum_nm + 0.5 * spacing(), spacing(), slices - 1);
    baked.thickness_error = midpoint_error(nodes, mids);
    if (baked.thickness_error <= kFilmStackTarget || 2 * slices - 1 > kMaxFilmStackSlices) break;
    std::vector<FilmFresnelRow> finer;
    finer.reserve(2 * slices - 1);
    for (std::size_t s = 0; s < slices; ++s) {
      finer.push_back(nodes[s]);
      if (s + 1 < slices) finer.push_back(mids[s]);
    }
    nodes = std::move(finer);
    slices = nodes.size();
  }
  baked.stack.minimum_nm = minimum_nm;
  baked.stack.maximum_nm = maximum_nm;
  baked.stack.slices.resize(slices);
  const auto split_sums = film_split_sums(samples);
  for (std::size_t s = 0; s < slices; ++s) {
    baked.stack.slices[s].fresnel = nodes[s];
    baked.stack.slices[s].preintegrated = split_sums->preintegrate(nodes[s]);
  }
  return baked;
}

runtime::FilmTable bake_film_table(const ReflectanceCurve& curve, std::size_t samples) {
  runtime::FilmTable table = fresnel_row(curve);
  table.preintegrated = film_split_sums(samples)->preintegrate(table.fresnel);
  return table;
}

runtime::FilmTable bake_coated_film_table(const ReflectanceCurve& in_air,
                                          const ReflectanceCurve& under_coat, const CoatInput& coat,
                                          std::size_t samples) {
  using runtime::FilmTable;
  const auto split_sums = film_split_sums(samples);
  runtime::FilmTable under = fresnel_row(under_coat);
  under.preintegrated = split_sums->preintegrate(under.fresnel);
  // Under a full coat layered_base takes nothing from the metal in air: zeros stand in.
  runtime::FilmTable air;
  air.preintegrated.assign(FilmTable::kViewNodes * FilmTable::kRoughnessNodes, Rgb{});
  if (coat.weight < 1.0) {
    air = fresnel_row(in_air);
    air.preintegrated = split_sums->preintegrate(air.fresnel);
  }
  runtime::FilmTable table = fresnel_row(LayeredCurve(in_air, under_coat, coat.weight, coat.ior,
                                                      coat.color, LayeredCurve::Part::base));
  runtime::CoatCoefficients tint_only;
  tint_only.ior = coat.ior;
  tint_only.color = coat.color;
  const CoatCurve dielectric(coat.ior);
  std::array<double, FilmTable::kViewNodes> coat_fbar{};
  std::array<Rgb, FilmTable::kViewNodes> tint{};
  const HammersleySet set(samples);
  for (std::size_t i = 0; i < FilmTable::kViewNodes; ++i) {
    coat_fbar[i] =
        SplitSumEstimator(set, integrated_view_cosine(i), coat.roughness).integrate(dielectric)[0];
    tint[i] = runtime::coat_tint(tint_only, runtime::film_table_view_cosine(i));
  }
  table.preintegrated.reserve(FilmTable::kViewNodes * FilmTable::kRoughnessNodes);
  for (std::size_t node = 0; node < under.preintegrated.size(); ++node) {
    const std::size_t i = node % FilmTable::kViewNodes;
    table.preintegrated.push_back(runtime::layered_base(
        air.preintegrated[node], under.preintegrated[node], tint[i], coat_fbar[i], coat.weight));
  }
  return table;
}

}  // namespace matc
