// How far an approximation is from the exact curve, per channel, over mu in [0, 1].
#pragma once

#include <cstddef>
#include <vector>

#include "matc/runtime/fresnel.h"
#include "matc/runtime/shader_basis.h"
#include "optics/reflectance_curve.h"

namespace matc {

// Errors are measured at this many cosines, mu_j = j / (count - 1). The count is odd and not
// 1 + a multiple of the basis grid's 999 intervals, so most points fall between basis samples and
// the interpolation the shaders do is part of what is measured.
inline constexpr std::size_t kAccuracySamples = 2001;

// "Exact" is the curve clamped at 0, as the shaders clamp F: a curve that dips below 0 (F82-tint
// with a low tint and F0) is measured against what a renderer can show.
struct ErrorStats {
  Rgb max_abs{};  // max over mu of |approximation - exact|
  Rgb rms{};      // root mean square over the same points
};

// Max and RMS of |approximation - exact| per channel, one cosine at a time.
class ErrorAccumulator {
 public:
  void add(const Rgb& approximation, const Rgb& exact);
  ErrorStats finish() const;

 private:
  ErrorStats stats_;
  Rgb sum_squares_{};
  std::size_t count_ = 0;
};

// The accuracy grid's cosine j, mu_j = j / (kAccuracySamples - 1).
double accuracy_grid_mu(std::size_t j);

// `approximation(mu)` (an Rgb) against `exact` clamped at 0 over the accuracy grid: what the
// shaders compute for a material, however they compute it.
template <typename Approximation>
ErrorStats measure_on_accuracy_grid(const ReflectanceCurve& exact,
                                    const Approximation& approximation) {
  ErrorAccumulator errors;
  for (std::size_t j = 0; j < kAccuracySamples; ++j) {
    const double mu = accuracy_grid_mu(j);
    Rgb reference = exact.at(mu);
    for (double& value : reference)
      value = value > 0.0 ? value : 0.0;
    errors.add(approximation(mu), reference);
  }
  return errors.finish();
}

// An exact curve evaluated once at the accuracy grid's cosines, which include the minimax solve's
// (kMinimaxCosines - 1 divides kAccuracySamples - 1): solving and measuring a spectral material
// then integrate each spectrum once. Other cosines go to the exact curve, which must outlive this.
class AccuracyGridCurve final : public ReflectanceCurve {
 public:
  explicit AccuracyGridCurve(const ReflectanceCurve& exact);
  Rgb at(double mu) const override;
  std::optional<Rgb> grazing_value() const override { return exact_.grazing_value(); }

 private:
  const ReflectanceCurve& exact_;
  std::vector<Rgb> values_;  // at mu_j = j / (kAccuracySamples - 1)
};

// The largest of the three channels' values: the "worst channel" the tables report.
double worst_channel(const Rgb& values);

struct FitAccuracy {
  std::size_t samples = kAccuracySamples;
  ErrorStats decomposition;  // ours: max(0, sum c_i b_i)
  ErrorStats schlick;        // Schlick with the exact F0
  ErrorStats f82_tint;       // Hoffman's F82-tint with the exact F0 and F(1/7)
};

FitAccuracy measure_accuracy(const ReflectanceCurve& curve,
                             const runtime::Coefficients& coefficients,
                             const runtime::ShaderBasis& shader_basis,
                             std::size_t samples = kAccuracySamples);

}  // namespace matc
