// Split-sum sampling of a GGX surface: for a view cosine and roughness, the half-vector cosines
// V.H and estimator weights G2(V, L) / G1(V) of reflections sampled from the visible normals.
// E[f(V.H) * weight] over the samples is the split-sum average of f (Karis 2013; the talk's Eq. 2).
#pragma once

#include <cstddef>
#include <vector>

namespace matc {

// A deterministic low-discrepancy set: Hammersley points u1 = (k + 1/2) / n, u2 = radical
// inverse of k in base 2, stored as the disk coordinates Heitz's sampler needs.
class HammersleySet {
 public:
  explicit HammersleySet(std::size_t count);
  std::size_t size() const { return disk_x_.size(); }
  const float* disk_x() const { return disk_x_.data(); }  // sqrt(u1) cos(2 pi u2)
  const float* disk_y() const { return disk_y_.data(); }  // sqrt(u1) sin(2 pi u2)

 private:
  std::vector<float> disk_x_;
  std::vector<float> disk_y_;
};

// The cosine at which the grazing column (NdotV = 0) is integrated: the split-sum integrand's
// limit there is approached, not evaluated, because G1(V) vanishes.
inline constexpr double kMinIntegratedNdotV = 1e-4;

// Fills vdoth[k] and weight[k] for every point of `set`: H is drawn from the GGX distribution of
// visible normals (Heitz 2018) for view cosine `ndotv` and alpha = roughness^2, L = reflect(-V, H);
// weight = G2 / G1 with Smith's height-correlated masking-shadowing, 0 where L is below the
// horizon.
void sample_microfacet_reflections(const HammersleySet& set, double ndotv, double roughness,
                                   float* vdoth, float* weight);

}  // namespace matc
