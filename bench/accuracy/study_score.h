// A basis' score on a test set, as the basis studies print it (basis_study.cpp,
// closed_form_basis_study.cpp): the worst and the mean of per-curve max errors, each curve solved
// by `solve` and measured through the basis as the shaders evaluate it.
#pragma once

#include <algorithm>
#include <cstddef>

#include "basis/basis_fit.h"
#include "fit/accuracy.h"
#include "test_sets.h"

namespace matc::bench {

struct Score {
  double worst = 0.0;
  double mean = 0.0;
};

template <typename Solve>  // runtime::Coefficients(const ReflectanceCurve&)
Score score(const TestSet& set, const FittedBasis& basis, const Solve& solve) {
  Score result;
  std::size_t count = 0;
  for (const TestCurve& curve : set.curves) {
    const FitAccuracy accuracy =
        measure_accuracy(*curve.cached, solve(*curve.cached), basis.shader);
    for (std::size_t c = 0; c < curve.channels; ++c) {
      result.worst = std::max(result.worst, accuracy.decomposition.max_abs[c]);
      result.mean += accuracy.decomposition.max_abs[c];
      ++count;
    }
  }
  result.mean /= static_cast<double>(count);
  return result;
}

}  // namespace matc::bench
