#include "matc/runtime/ltc_following.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "texel_axis.h"

namespace matc::runtime {

LtcLitPolygon ltc_lit_polygon(const LtcInverse& inverse, std::span<const Vec3> vertices) {
  LtcLitPolygon lit;
  lit.form_factor = ltc_polygon_vector_form_factor(inverse, vertices);
  const Vec3& f = lit.form_factor;
  lit.integral = std::min(1.0, f[2]);
  const Vec3 back = inverse.apply_adjugate(f);
  if (dot(back, back) > 0.0) lit.direction = normalize(back);
  return lit;
}

double ggx_lobe_cosine(double ndotv, double roughness, const Vec3& light) {
  if (light[2] <= 0.0) return 0.0;
  const double nv = std::clamp(ndotv, kFollowingMinNdotV, 1.0);
  const double alpha = std::max(roughness * roughness, kFollowingMinAlpha);
  const double a2 = alpha * alpha;
  const Vec3 half = normalize(plus({std::sqrt(1.0 - nv * nv), 0.0, nv}, light));
  // H.z^2 (a2 - 1) + 1 without its cancellation near the peak (the shaders run in float32).
  const double d = half[0] * half[0] + half[1] * half[1] + half[2] * half[2] * a2;
  const double distribution = a2 / (std::numbers::pi * d * d);
  // Height-correlated Smith, as 0.5 / (NdotL Lambda-term(V) + NdotV Lambda-term(L)).
  const double nl = light[2];
  const double visibility =
      0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2));
  return distribution * visibility * nl;
}

LtcFollowing ltc_following(const LtcInverse& inverse, double ndotv, double roughness, double albedo,
                           std::span<const Vec3> vertices) {
  const LtcLitPolygon lit = ltc_lit_polygon(inverse, vertices);
  LtcFollowing following;
  following.integral = lit.integral;
  // V.H for the light's direction L: sqrt((1 + V.L) / 2).
  const double nv = unit_clamp(ndotv);
  const Vec3 view{std::sqrt(1.0 - nv * nv), 0.0, nv};
  following.vdoth = std::sqrt(unit_clamp(0.5 + 0.5 * dot(view, lit.direction)));
  // The LTC's density at L, D_o(M^-1 L / |M^-1 L|) det(M^-1) / |M^-1 L|^3, is, with M^-1 L
  // parallel to the form factor f and L = adj u / |adj u| for u = f / |f|:
  // u.z |adj u|^3 / (pi det^2). The unit u keeps every factor well inside a float's range.
  const Vec3& f = lit.form_factor;
  const double length_f = std::sqrt(dot(f, f));
  const Vec3 u = length_f > 0.0 ? scaled(f, 1.0 / length_f) : Vec3{};
  const double det = inverse.determinant();
  const Vec3 back = inverse.apply_adjugate(u);
  const double back_length = std::sqrt(dot(back, back));
  const double lobe = ggx_lobe_cosine(ndotv, roughness, lit.direction);
  following.ratio =
      std::clamp(lobe * std::numbers::pi * det * det /
                     std::max(albedo * u[2] * back_length * back_length * back_length, 1e-30),
                 0.0, kMaxShapeRatio);
  following.extent = std::sqrt(std::min(length_f, 1.0));
  const double size = following.extent * (2.0 - following.extent);
  following.shaped = lit.integral * (following.ratio + size * (1.0 - following.ratio));
  return following;
}

Rgb polygon_light_ltc_following(const Coefficients& coefficients, const LutView& lut,
                                const ShaderBasis& basis, const LtcTableView& ltc, double ndotv,
                                double roughness, std::span<const Vec3> vertices) {
  const std::array<double, kBasisSize> bbar = sample_lut(lut, ndotv, roughness);
  const double albedo = bbar[0];
  const LtcFollowing following =
      ltc_following(sample_ltc(ltc, ndotv, roughness), ndotv, roughness, albedo, vertices);
  const Rgb at_light = evaluate_fresnel(coefficients, basis, following.vdoth);
  const Rgb lobe = combine(coefficients, bbar);  // Fbar
  // A light over a small part of the lobe sees the Fresnel where it lies, one over all of it the
  // lobe's average.
  Rgb radiance{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double light = albedo * at_light[c];
    radiance[c] = following.shaped * (light + following.integral * (lobe[c] - light));
  }
  return radiance;
}

}  // namespace matc::runtime
