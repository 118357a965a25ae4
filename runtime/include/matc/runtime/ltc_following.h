// The quality level of area lights (issue #31, docs/ltc.md): the LTC path of ltc.h with the
// Fresnel and the lobe's shape following the light across the lobe. The one-shape path multiplies
// the LTC's integral I by one preintegrated Fresnel Fbar for the whole lobe, which is wrong for a
// light that covers part of it wherever F varies with angle, and its four-parameter shape misses
// the GGX lobe's tail and horizon. Here, from where the light lies on the lobe (the direction of
// the polygon's vector form factor, taken back through M):
//   - shape: I' = I * mix(r, 1, s), r = (GGX f cos at that direction) / (E * the LTC's density
//     there), clamped to [0, kMaxShapeRatio], and s = q (2 - q) for q = sqrt(|vector form
//     factor|), from the light's size in the cosine's space (a small light takes the lobe's own
//     density, one over much of the lobe the LTC's integral);
//   - Fresnel: L = I' * mix(E F(V.H), Fbar, I), F at the half vector of that direction.
// E is the lobe's albedo, bbar_0 of the preintegrated table.
#pragma once

#include <span>

#include "matc/runtime/fresnel.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"

namespace matc::runtime {

inline constexpr double kMaxShapeRatio = 4.0;
// The GGX lobe's limits, as GgxLobe (compiler) and the shaders take them.
inline constexpr double kFollowingMinAlpha = 1e-4;
inline constexpr double kFollowingMinNdotV = 1e-3;

// The LTC's integral over a polygon and where it lies: the vector form factor in the cosine's
// space, and its direction taken back through M (a unit vector in the shading frame, +z when
// nothing is lit). M is the adjugate of M^-1 up to 1 / (ad - bc) > 0 in every fitted texel.
struct LtcLitPolygon {
  double integral = 0.0;  // I_ltc
  Vec3 form_factor{};     // z is I_ltc before its clamp at 1
  Vec3 direction{0.0, 0.0, 1.0};
};
LtcLitPolygon ltc_lit_polygon(const LtcInverse& inverse, std::span<const Vec3> vertices);

// The GGX lobe without Fresnel, f(V, L) cos(theta_L) (height-correlated Smith), at a unit L in the
// shading frame, for the view at NdotV: what the LTC approximates.
double ggx_lobe_cosine(double ndotv, double roughness, const Vec3& light);

// The quality level's geometry for one polygon (the shaders' matc_ltc_following_geometry).
struct LtcFollowing {
  double integral = 0.0;  // I_ltc: the Fresnel's blend weight
  double ratio = 1.0;     // r: the lobe over the LTC at the light's direction, clamped
  double extent = 0.0;    // q = sqrt(|vector form factor|), at most 1: s = q (2 - q)
  double shaped = 0.0;    // I' = I mix(r, 1, s)
  double vdoth = 0.0;     // V.H at the light's direction on the lobe
};
LtcFollowing ltc_following(const LtcInverse& inverse, double ndotv, double roughness, double albedo,
                           std::span<const Vec3> vertices);

// The quality level's radiance from a polygonal light of radiance 1 (vertices in the shading
// frame), per channel: what the shaders' matc_ltc_*_light_following compute.
Rgb polygon_light_ltc_following(const Coefficients& coefficients, const LutView& lut,
                                const ShaderBasis& basis, const LtcTableView& ltc, double ndotv,
                                double roughness, std::span<const Vec3> vertices);

}  // namespace matc::runtime
