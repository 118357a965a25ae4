// The exact reflected radiance of a polygonal light, the reference the LTC path is measured
// against: the integral over the polygon of f(V, L) F(V.H) cos(theta_L) (GGX, height-correlated
// Smith, any Fresnel curve) for radiance 1, two-sided, estimated by Monte Carlo with multiple
// importance sampling (Veach's balance heuristic) of the light's area and the lobe's visible
// normals, with the estimate's standard error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

#include "ltc/ggx_lobe.h"
#include "matc/runtime/fresnel.h"

namespace matc {

inline constexpr std::size_t kDefaultLightSamples = std::size_t{1} << 20;

struct AreaLightEstimate {
  runtime::Rgb mean{};
  runtime::Rgb standard_error{};
};

// F at a cosine V.H, per channel (a constant 1 integrates the lobe alone).
using FresnelAtCosine = std::function<runtime::Rgb(double)>;

// `samples` pairs (one light sample, one lobe sample each) from a fixed seed: the same inputs give
// the same estimate. The polygon must pass check_polygon_light (convex, planar).
AreaLightEstimate integrate_polygon_light(const GgxLobe& lobe, std::span<const Vec3> vertices,
                                          const FresnelAtCosine& fresnel, std::size_t samples,
                                          std::uint64_t seed = 1);

}  // namespace matc
