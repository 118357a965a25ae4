// Schlick's and F82-tint's angular lobes as a basis view, so that their split sums are baked and
// sampled exactly like ours: b_1 = (1 - mu)^5, b_2 = mu (1 - mu)^6, b_3 = 0. A table baked from
// it holds (albedo, Schlick lobe, F82 lobe, 0) per texel, so Schlick's split sum is
// F0 x + (1 - F0) y from one fetch: what the accuracy study, the renders and the cost benchmark
// compare against.
#pragma once

#include <cstddef>
#include <vector>

#include "matc/runtime/basis.h"

namespace matc {

class ComparisonLobes {
 public:
  // Tabulated at `samples` cosines like the basis (use paper_basis().samples()).
  explicit ComparisonLobes(std::size_t samples);
  runtime::BasisView view() const { return {{schlick_, f82_, zero_}, {1, 2}}; }

 private:
  std::vector<double> schlick_;
  std::vector<double> f82_;
  std::vector<double> zero_;
};

}  // namespace matc
