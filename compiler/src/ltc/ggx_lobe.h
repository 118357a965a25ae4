// The GGX reflection lobe without Fresnel, f(V, L) cos(theta_L), for one view direction in the
// shading frame (normal +z, V in the xz-plane): what the LTC fit approximates and what the
// area-light reference integrates. Height-correlated Smith masking-shadowing, alpha =
// roughness^2, reflections drawn from the distribution of visible normals (Heitz 2018) like the
// preintegrated table's.
#pragma once

#include <cstddef>

#include "matc/runtime/ltc.h"

namespace matc {

using runtime::Vec3;

// Below this alpha the lobe is a near-delta that neither the fit nor the sampling resolves.
inline constexpr double kMinLobeAlpha = 1e-4;
// Below this view cosine the lobe is evaluated at this cosine (the grazing column's limit).
inline constexpr double kMinLobeNdotV = 1e-3;

class GgxLobe {
 public:
  GgxLobe(double ndotv, double roughness);

  struct Value {
    double lobe = 0.0;   // f(V, L) cos(theta_L), 0 below the horizon
    double pdf = 0.0;    // density of sample() at L (solid angle)
    double vdoth = 0.0;  // V.H, the Fresnel's cosine
  };
  Value evaluate(const Vec3& light) const;

  // A reflection from the visible normals for a point (u1, u2) of the unit square; it may point
  // below the horizon (then evaluate() gives 0).
  Vec3 sample(double u1, double u2) const;

  // The directional albedo, the integral of f cos over the hemisphere, from n x n stratified
  // samples of sample().
  double albedo(std::size_t samples_per_axis) const;

  const Vec3& view() const { return view_; }
  double alpha() const { return alpha_; }

 private:
  double lambda(double cos_theta) const;

  double alpha_;
  Vec3 view_;
  double lambda_view_;
};

}  // namespace matc
