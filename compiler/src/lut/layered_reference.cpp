#include "lut/layered_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "base/rgb_mean.h"
#include "lut/split_sum_reference.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/vec3.h"
#include "optics/coat.h"

namespace matc {
namespace {

using runtime::Vec3;

constexpr int kMaxBounces = 64;

// A uniform double in [0, 1) from the generator's top 53 bits: the same numbers from every
// standard library (std::uniform_real_distribution's are not specified).
double uniform(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1p-53;
}

// A visible normal from two draws made in sequence: the order in which a call's arguments are
// evaluated is unspecified (GCC and Clang differ), and it would change every path.
Vec3 draw_visible_normal(const Vec3& w, double alpha, std::mt19937_64& random);
constexpr double kMinAlpha = 1e-4;  // a smooth surface, sampled as a very sharp GGX

// Smith's Lambda for GGX at direction w (the normal is +z).
double ggx_lambda(const Vec3& w, double alpha) {
  const double cos2 = w[2] * w[2];
  if (cos2 >= 1.0) return 0.0;
  const double tan2 = (1.0 - cos2) / std::max(cos2, 1e-300);
  return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

// A microfacet normal from GGX's distribution of normals visible from w (w.z > 0; Heitz 2018).
Vec3 sample_visible_normal(const Vec3& w, double alpha, double u1, double u2) {
  const Vec3 stretched = runtime::normalize({alpha * w[0], alpha * w[1], w[2]});
  const double length_squared = stretched[0] * stretched[0] + stretched[1] * stretched[1];
  const Vec3 t1 = length_squared > 0.0 ? runtime::scaled({-stretched[1], stretched[0], 0.0},
                                                         1.0 / std::sqrt(length_squared))
                                       : Vec3{1.0, 0.0, 0.0};
  const Vec3 t2 = runtime::cross(stretched, t1);
  const double r = std::sqrt(u1);
  const double phi = 2.0 * std::numbers::pi * u2;
  const double p1 = r * std::cos(phi);
  const double s = 0.5 * (1.0 + stretched[2]);
  const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
  const double p3 = std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2));
  const Vec3 n = runtime::plus(runtime::plus(runtime::scaled(t1, p1), runtime::scaled(t2, p2)),
                               runtime::scaled(stretched, p3));
  return runtime::normalize({alpha * n[0], alpha * n[1], std::max(0.0, n[2])});
}

Vec3 draw_visible_normal(const Vec3& w, double alpha, std::mt19937_64& random) {
  const double u1 = uniform(random);
  const double u2 = uniform(random);
  return sample_visible_normal(w, alpha, u1, u2);
}

// One scattering event on a dielectric microsurface seen from w (w.z > 0, normal +z, relative
// index `eta` of the far side): reflected (out.z > 0) or transmitted (out.z < 0), chosen by the
// exact Fresnel; false where the path leaves the microsurface's single-scattering model.
struct Scatter {
  Vec3 out{};
  double weight = 1.0;
};
bool scatter_dielectric(const Vec3& w, double alpha, double eta, std::mt19937_64& random,
                        Scatter& result) {
  const Vec3 m = draw_visible_normal(w, alpha, random);
  const double cos_i = std::clamp(runtime::dot(w, m), 0.0, 1.0);
  const double fresnel = fresnel_exact(cos_i, {eta, 0.0});
  const double lambda_in = ggx_lambda(w, alpha);
  if (uniform(random) < fresnel) {
    result.out = runtime::minus(runtime::scaled(m, 2.0 * cos_i), w);
    if (result.out[2] <= 0.0) return false;
    result.weight = (1.0 + lambda_in) / (1.0 + lambda_in + ggx_lambda(result.out, alpha));
    return true;
  }
  const double ratio = 1.0 / eta;  // incident index over transmitted
  const double cos_t2 = 1.0 - ratio * ratio * (1.0 - cos_i * cos_i);
  if (cos_t2 <= 0.0) return false;  // not reached: Fresnel is 1 under total internal reflection
  result.out = runtime::plus(runtime::scaled(w, -ratio),
                             runtime::scaled(m, ratio * cos_i - std::sqrt(cos_t2)));
  if (result.out[2] >= 0.0) return false;
  result.weight = 1.0 / (1.0 + ggx_lambda(result.out, alpha));  // G1 of the transmitted side
  return true;
}

Vec3 mirrored(const Vec3& v) {
  return {v[0], v[1], -v[2]};
}

// One path into the coated surface from w: what it carries out per channel (0 where absorbed or
// lost to the microsurfaces' single scattering).
Rgb trace_coated(const LayeredSurface& surface, const Vec3& w, std::mt19937_64& random) {
  const CoatInput& coat = surface.coat;
  const double coat_alpha = std::max(coat.roughness * coat.roughness, kMinAlpha);
  const double base_alpha = std::max(surface.base_roughness * surface.base_roughness, kMinAlpha);
  Scatter event;
  if (!scatter_dielectric(w, coat_alpha, coat.ior, random, event)) return {};
  if (event.out[2] > 0.0) return {event.weight, event.weight, event.weight};
  Rgb throughput = {event.weight, event.weight, event.weight};
  Vec3 down = event.out;  // travelling down inside the coat
  const auto absorb = [&](double cosine) {
    for (std::size_t c = 0; c < 3; ++c)
      throughput[c] *= coat_round_trip_transmittance(coat.color[c], 2.0 * std::abs(cosine));
  };
  for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
    absorb(down[2]);
    // The metal, seen from where the light came from.
    const Vec3 toward = runtime::scaled(down, -1.0);
    const Vec3 m = draw_visible_normal(toward, base_alpha, random);
    const double cos_i = std::clamp(runtime::dot(toward, m), 0.0, 1.0);
    const Rgb reflectance = surface.metal_in_coat.at(cos_i);
    const Vec3 up = runtime::minus(runtime::scaled(m, 2.0 * cos_i), toward);
    if (up[2] <= 0.0) return {};
    const double lambda_in = ggx_lambda(toward, base_alpha);
    const double weight = (1.0 + lambda_in) / (1.0 + lambda_in + ggx_lambda(up, base_alpha));
    for (std::size_t c = 0; c < 3; ++c)
      throughput[c] *= weight * std::max(reflectance[c], 0.0);
    absorb(up[2]);
    // The coat's underside, in a frame mirrored so that its normal is +z.
    if (!scatter_dielectric(mirrored(runtime::scaled(up, -1.0)), coat_alpha, 1.0 / coat.ior, random,
                            event))
      return {};
    for (double& value : throughput)
      value *= event.weight;
    if (event.out[2] < 0.0) return throughput;  // transmitted: out into the air
    down = mirrored(event.out);                 // reflected back down
  }
  return {};
}

}  // namespace

Rgb layered_split_sum(const ReflectanceCurve& in_air, const ReflectanceCurve& under_coat,
                      const CoatInput& coat, double ndotv, double base_roughness) {
  const SplitSumEstimator base_lobe(ndotv, base_roughness);
  const double coat_fbar =
      SplitSumEstimator(ndotv, coat.roughness).integrate(CoatCurve(coat.ior))[0];
  runtime::CoatCoefficients tint_only;
  tint_only.ior = coat.ior;
  tint_only.color = coat.color;
  const Rgb base =
      runtime::layered_base(base_lobe.integrate(in_air), base_lobe.integrate(under_coat),
                            runtime::coat_tint(tint_only, ndotv), coat_fbar, coat.weight);
  const double coat_part = coat.weight * coat_fbar;
  return {base[0] + coat_part, base[1] + coat_part, base[2] + coat_part};
}

LayeredEstimate layered_albedo(const LayeredSurface& surface, double ndotv, std::size_t paths,
                               std::uint64_t seed) {
  const double mu = std::clamp(ndotv, 1e-4, 1.0);
  const Vec3 w = {std::sqrt(1.0 - mu * mu), 0.0, mu};
  std::mt19937_64 random(seed);
  RgbMean paths_out;
  for (std::size_t i = 0; i < paths; ++i)
    paths_out.add(trace_coated(surface, w, random));
  const LayeredEstimate coated{paths_out.mean(), paths_out.standard_error()};
  const auto count = static_cast<double>(paths);
  const double weight = surface.coat.weight;
  if (weight >= 1.0) return coated;
  // The uncovered part: the bare metal in air, one GGX scattering.
  std::mt19937_64 bare_random(seed + 1);
  const double alpha = std::max(surface.base_roughness * surface.base_roughness, kMinAlpha);
  Rgb bare{};
  for (std::size_t i = 0; i < paths; ++i) {
    const Vec3 m = draw_visible_normal(w, alpha, bare_random);
    const double cos_i = std::clamp(runtime::dot(w, m), 0.0, 1.0);
    const Vec3 out = runtime::minus(runtime::scaled(m, 2.0 * cos_i), w);
    if (out[2] <= 0.0) continue;
    const double lambda_in = ggx_lambda(w, alpha);
    const double g = (1.0 + lambda_in) / (1.0 + lambda_in + ggx_lambda(out, alpha));
    const Rgb f = surface.in_air.at(cos_i);
    for (std::size_t c = 0; c < 3; ++c)
      bare[c] += g * f[c];
  }
  LayeredEstimate mixed;
  for (std::size_t c = 0; c < 3; ++c) {
    mixed.mean[c] = weight * coated.mean[c] + (1.0 - weight) * bare[c] / count;
    mixed.standard_error[c] = weight * coated.standard_error[c];
  }
  return mixed;
}

}  // namespace matc
