#include "matc/runtime/powers_basis.h"

#include <algorithm>
#include <vector>

namespace matc::runtime {

namespace {

// The same grid as the fitted bases' checked-in tables.
constexpr std::size_t kSamples = 1000;

using Tables = std::array<std::vector<double>, kBasisSize - 1>;

template <typename Evaluate>
Tables tabulate(Evaluate evaluate) {
  Tables result;
  for (std::vector<double>& table : result)
    table.resize(kSamples);
  for (std::size_t j = 0; j < kSamples; ++j) {
    const auto b = evaluate(static_cast<double>(j) / (kSamples - 1));
    for (std::size_t i = 0; i < result.size(); ++i)
      result[i][j] = b[i + 1];
  }
  return result;
}

std::size_t grid_index(double mu) {
  return static_cast<std::size_t>(mu * (kSamples - 1) + 0.5);
}

}  // namespace

BasisView powers_basis() {
  static const Tables tables = tabulate(evaluate_powers_basis);
  // Probes at the peaks of b_2 (mu = 1/4) and b_3 (mu = 1/10), for the collocation solve.
  return {
      {tables[0], tables[1], tables[2]}, {grid_index(0.25), grid_index(0.1)}, BasisKind::powers};
}

BasisView f82_basis() {
  static const Tables tables = tabulate(evaluate_f82_basis);
  // Probes at the peaks of b_2 = mu m^6 (mu = 1/7) and b_3 = mu m^11 (mu = 1/12).
  return {{tables[0], tables[1], tables[2]},
          {grid_index(1.0 / 7.0), grid_index(1.0 / 12.0)},
          BasisKind::f82};
}

}  // namespace matc::runtime
