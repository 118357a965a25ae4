#include "compile/film_tables.h"

#include <algorithm>

#include "lut/microfacet_samples.h"
#include "lut/split_sum_reference.h"

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

}  // namespace

runtime::FilmTable bake_film_table(const ReflectanceCurve& curve, std::size_t samples) {
  using runtime::FilmTable;
  FilmTable table;
  for (std::size_t i = 0; i < FilmTable::kCosineNodes; ++i)
    table.fresnel[i] = curve.at(runtime::film_table_cosine(i));
  const FresnelTableCurve fresnel(table);
  const HammersleySet set(samples);
  table.preintegrated.reserve(FilmTable::kViewNodes * FilmTable::kRoughnessNodes);
  for (std::size_t j = 0; j < FilmTable::kRoughnessNodes; ++j) {
    for (std::size_t i = 0; i < FilmTable::kViewNodes; ++i) {
      const double ndotv = std::max(runtime::film_table_view_cosine(i), kMinIntegratedNdotV);
      table.preintegrated.push_back(
          SplitSumEstimator(set, ndotv, runtime::film_table_roughness(j)).integrate(fresnel));
    }
  }
  return table;
}

}  // namespace matc
