// The worst and the mean of per-curve max errors over a set of curves: what the accuracy tables
// print (accuracy_table.cpp, f82_basis_study.cpp).
#pragma once

#include <algorithm>
#include <cstddef>

#include "fit/accuracy.h"

namespace matc::bench {

struct Totals {
  double worst = 0.0;
  double sum_of_max = 0.0;
  std::size_t curves = 0;
  // Each channel of an RGB curve counts as one curve.
  void add(const ErrorStats& stats) {
    for (const double value : stats.max_abs)
      add_one(value);
  }
  void add_one(double max_error) {
    worst = std::max(worst, max_error);
    sum_of_max += max_error;
    ++curves;
  }
  double mean() const { return sum_of_max / static_cast<double>(curves); }
};

}  // namespace matc::bench
