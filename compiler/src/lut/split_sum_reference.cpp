#include "lut/split_sum_reference.h"

#include <algorithm>

namespace matc {

TabulatedCurve::TabulatedCurve(const ReflectanceCurve& curve, std::size_t count) {
  values_.reserve(count);
  for (std::size_t j = 0; j < count; ++j) {
    values_.push_back(curve.at(static_cast<double>(j) / static_cast<double>(count - 1)));
  }
}

Rgb TabulatedCurve::at(double mu) const {
  const double position = std::clamp(mu, 0.0, 1.0) * static_cast<double>(values_.size() - 1);
  const std::size_t left = std::min(static_cast<std::size_t>(position), values_.size() - 2);
  const double t = position - static_cast<double>(left);
  Rgb result{};
  for (std::size_t c = 0; c < 3; ++c) {
    result[c] = values_[left][c] + t * (values_[left + 1][c] - values_[left][c]);
  }
  return result;
}

SplitSumEstimator::SplitSumEstimator(double ndotv, double roughness, std::size_t samples)
    : SplitSumEstimator(HammersleySet(samples), ndotv, roughness) {}

SplitSumEstimator::SplitSumEstimator(const HammersleySet& set, double ndotv, double roughness)
    : vdoth_(set.size()), weight_(set.size()) {
  sample_microfacet_reflections(set, ndotv, roughness, vdoth_.data(), weight_.data());
}

Rgb SplitSumEstimator::integrate(const ReflectanceCurve& curve) const {
  Rgb sum{};
  for (std::size_t k = 0; k < vdoth_.size(); ++k) {
    if (weight_[k] <= 0.0f) continue;
    const Rgb f = curve.at(vdoth_[k]);
    for (std::size_t c = 0; c < 3; ++c)
      sum[c] += weight_[k] * f[c];
  }
  for (double& value : sum)
    value /= static_cast<double>(vdoth_.size());
  return sum;
}

}  // namespace matc
