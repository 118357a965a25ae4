// The preintegrated Fresnel of an exact curve, computed directly (no basis, no table): the
// reference that Fbar from the LUT is measured against.
#pragma once

#include <cstddef>
#include <vector>

#include "lut/microfacet_samples.h"
#include "optics/reflectance_curve.h"

namespace matc {

inline constexpr std::size_t kReferenceSamples = 1u << 16;
inline constexpr std::size_t kReferenceCurveSamples = 4096;

// An RGB curve tabulated at mu_j = j / (count - 1), evaluated by linear interpolation; tabulating
// once makes many reference integrals of an expensive (spectral) curve affordable.
class TabulatedCurve final : public ReflectanceCurve {
 public:
  explicit TabulatedCurve(const ReflectanceCurve& curve,
                          std::size_t count = kReferenceCurveSamples);
  Rgb at(double mu) const override;

 private:
  std::vector<Rgb> values_;
};

// The microfacet samples of one (NdotV, roughness), reusable for any number of curves.
class SplitSumEstimator {
 public:
  SplitSumEstimator(double ndotv, double roughness, std::size_t samples = kReferenceSamples);
  // The same over a set of points shared by many estimators (a table's nodes).
  SplitSumEstimator(const HammersleySet& set, double ndotv, double roughness);
  // E_h[F(V.H) G2/G1] per channel.
  Rgb integrate(const ReflectanceCurve& curve) const;

 private:
  std::vector<float> vdoth_;
  std::vector<float> weight_;
};

}  // namespace matc
