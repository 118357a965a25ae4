#include "matc/runtime/powers_basis.h"

#include <algorithm>
#include <vector>

namespace matc::runtime {

BasisView powers_basis() {
  // The same grid as the fitted bases' checked-in tables.
  constexpr std::size_t kSamples = 1000;
  static const std::array<std::vector<double>, kBasisSize - 1> tables = [] {
    std::array<std::vector<double>, kBasisSize - 1> result;
    for (std::vector<double>& table : result)
      table.resize(kSamples);
    for (std::size_t j = 0; j < kSamples; ++j) {
      const auto b = evaluate_powers_basis(static_cast<double>(j) / (kSamples - 1));
      for (std::size_t i = 0; i < result.size(); ++i)
        result[i][j] = b[i + 1];
    }
    return result;
  }();
  // Probes at the peaks of b_2 (mu = 1/4) and b_3 (mu = 1/10), for the collocation solve.
  const auto index = [](double mu) { return static_cast<std::size_t>(mu * (kSamples - 1) + 0.5); };
  return {{tables[0], tables[1], tables[2]}, {index(0.25), index(0.1)}, BasisKind::powers};
}

}  // namespace matc::runtime
