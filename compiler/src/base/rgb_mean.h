// The mean of RGB samples and its standard error, for the Monte-Carlo references (the area-light
// integral, the layered coat).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "matc/runtime/fresnel.h"

namespace matc {

class RgbMean {
 public:
  void add(const runtime::Rgb& value) {
    for (std::size_t c = 0; c < 3; ++c) {
      sum_[c] += value[c];
      sum_squares_[c] += value[c] * value[c];
    }
    ++count_;
  }
  runtime::Rgb mean() const {
    runtime::Rgb mean{};
    for (std::size_t c = 0; c < 3; ++c)
      mean[c] = sum_[c] / static_cast<double>(std::max<std::size_t>(count_, 1));
    return mean;
  }
  // sqrt(sample variance / count), the variance taken with n - 1.
  runtime::Rgb standard_error() const {
    const auto n = static_cast<double>(count_);
    const runtime::Rgb m = mean();
    runtime::Rgb error{};
    for (std::size_t c = 0; c < 3; ++c) {
      const double variance = std::max(0.0, sum_squares_[c] / std::max(n, 1.0) - m[c] * m[c]);
      error[c] = std::sqrt(variance / std::max(1.0, n - 1.0));
    }
    return error;
  }

 private:
  runtime::Rgb sum_{};
  runtime::Rgb sum_squares_{};
  std::size_t count_ = 0;
};

}  // namespace matc
