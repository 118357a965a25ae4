#include "compile/film_tables.h"

#include <algorithm>

#include "lut/microfacet_samples.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/coat.h"
#include "optics/coat.h"

namespace matc {
namespace {

// The F table as a curve, what the split sums of its nodes integrate.
class FresnelTableCurve final : public ReflectanceCurve {
 public:
  explicit FresnelTableCurve(const runtime::FilmTable& table) : table_(table) {}
  Rgb at(double mu) const override { return runtime::film_fresnel(table_, mu); }

 private:
  const runtime::FilmTable& table_;
};

// The view cosine the split sums integrate at node i.
double integrated_view_cosine(std::size_t i) {
  return std::max(runtime::film_table_view_cosine(i), kMinIntegratedNdotV);
}

// Fills table.preintegrated with the split sums of its F row over `set`.
void bake_preintegrated_rows(runtime::FilmTable& table, const HammersleySet& set) {
  using runtime::FilmTable;
  const FresnelTableCurve fresnel(table);
  table.preintegrated.clear();
  table.preintegrated.reserve(FilmTable::kViewNodes * FilmTable::kRoughnessNodes);
  for (std::size_t j = 0; j < FilmTable::kRoughnessNodes; ++j) {
    for (std::size_t i = 0; i < FilmTable::kViewNodes; ++i) {
      table.preintegrated.push_back(
          SplitSumEstimator(set, integrated_view_cosine(i), runtime::film_table_roughness(j))
              .integrate(fresnel));
    }
  }
}

runtime::FilmTable fresnel_row(const ReflectanceCurve& curve) {
  runtime::FilmTable table;
  for (std::size_t i = 0; i < runtime::FilmTable::kCosineNodes; ++i)
    table.fresnel[i] = curve.at(runtime::film_table_cosine(i));
  return table;
}

}  // namespace

runtime::FilmTable bake_film_table(const ReflectanceCurve& curve, std::size_t samples) {
  runtime::FilmTable table = fresnel_row(curve);
  bake_preintegrated_rows(table, HammersleySet(samples));
  return table;
}

runtime::FilmTable bake_coated_film_table(const ReflectanceCurve& in_air,
                                          const ReflectanceCurve& under_coat, const CoatInput& coat,
                                          std::size_t samples) {
  using runtime::FilmTable;
  const HammersleySet set(samples);
  runtime::FilmTable under = fresnel_row(under_coat);
  bake_preintegrated_rows(under, set);
  // Under a full coat layered_base takes nothing from the metal in air: zeros stand in.
  runtime::FilmTable air;
  air.preintegrated.assign(FilmTable::kViewNodes * FilmTable::kRoughnessNodes, Rgb{});
  if (coat.weight < 1.0) {
    air = fresnel_row(in_air);
    bake_preintegrated_rows(air, set);
  }
  runtime::FilmTable table = fresnel_row(LayeredCurve(in_air, under_coat, coat.weight, coat.ior,
                                                      coat.color, LayeredCurve::Part::base));
  runtime::CoatCoefficients tint_only;
  tint_only.ior = coat.ior;
  tint_only.color = coat.color;
  const CoatCurve dielectric(coat.ior);
  std::array<double, FilmTable::kViewNodes> coat_fbar{};
  std::array<Rgb, FilmTable::kViewNodes> tint{};
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
