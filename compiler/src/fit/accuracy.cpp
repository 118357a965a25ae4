#include "fit/accuracy.h"

#include <algorithm>
#include <cmath>

#include "optics/fresnel.h"

namespace matc {

void ErrorAccumulator::add(const Rgb& approximation, const Rgb& exact) {
  for (std::size_t c = 0; c < 3; ++c) {
    const double error = std::abs(approximation[c] - exact[c]);
    stats_.max_abs[c] = std::max(stats_.max_abs[c], error);
    sum_squares_[c] += error * error;
  }
  ++count_;
}

ErrorStats ErrorAccumulator::finish() const {
  ErrorStats result = stats_;
  for (std::size_t c = 0; c < 3; ++c) {
    result.rms[c] = std::sqrt(sum_squares_[c] / static_cast<double>(count_));
  }
  return result;
}

double accuracy_grid_mu(std::size_t j) {
  return static_cast<double>(j) / static_cast<double>(kAccuracySamples - 1);
}

AccuracyGridCurve::AccuracyGridCurve(const ReflectanceCurve& exact) : exact_(exact) {
  values_.reserve(kAccuracySamples);
  for (std::size_t j = 0; j < kAccuracySamples; ++j)
    values_.push_back(exact.at(accuracy_grid_mu(j)));
}

Rgb AccuracyGridCurve::at(double mu) const {
  const double index = std::round(mu * static_cast<double>(kAccuracySamples - 1));
  if (index >= 0.0 && index < static_cast<double>(kAccuracySamples) &&
      accuracy_grid_mu(static_cast<std::size_t>(index)) == mu)
    return values_[static_cast<std::size_t>(index)];
  return exact_.at(mu);
}

double worst_channel(const Rgb& values) {
  return std::max({values[0], values[1], values[2]});
}

FitAccuracy measure_accuracy(const ReflectanceCurve& curve,
                             const runtime::Coefficients& coefficients,
                             const runtime::ShaderBasis& shader_basis, std::size_t samples) {
  const Rgb f0 = curve.at(1.0);
  const Rgb f82 = curve.at(kF82MuBar);
  ErrorAccumulator ours;
  ErrorAccumulator schlick;
  ErrorAccumulator f82_tint;
  for (std::size_t j = 0; j < samples; ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(samples - 1);
    // A negative reflectance is no reflectance: the shaders clamp F at 0, and so does the
    // reference. Only curves that dip below 0 are affected (F82-tint with a low tint and F0).
    Rgb exact = curve.at(mu);
    for (double& value : exact)
      value = std::max(value, 0.0);
    Rgb schlick_value{};
    Rgb f82_value{};
    for (std::size_t c = 0; c < 3; ++c) {
      schlick_value[c] = fresnel_schlick(mu, f0[c]);
      f82_value[c] = fresnel_f82_tint(mu, f0[c], f82[c]);
    }
    ours.add(runtime::evaluate_fresnel(coefficients, shader_basis, mu), exact);
    schlick.add(schlick_value, exact);
    f82_tint.add(f82_value, exact);
  }
  FitAccuracy result;
  result.samples = samples;
  result.decomposition = ours.finish();
  result.schlick = schlick.finish();
  result.f82_tint = f82_tint.finish();
  return result;
}

}  // namespace matc
