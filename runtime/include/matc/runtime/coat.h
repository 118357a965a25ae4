// A metal under a dielectric coat as the shaders evaluate it (docs/coating.md): two lobes, the
// coat's (weight x the coat's Fresnel, at the coat's roughness) and the base's (the metal in air
// mixed with the metal seen through the coat, at the base's roughness).
#pragma once

#include <algorithm>

#include <span>

#include "matc/runtime/film_table.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"

namespace matc::runtime {

// What a coated material's shaders hold beside the metal's own coefficients.
struct CoatCoefficients {
  // The metal seen through the coat: its curve at the metal/coat interface, at the cosines
  // inside the coat; per channel, fitted with the basis.
  Coefficients under_coat{};
  ChannelCoefficients coat{};  // the coat's dielectric Fresnel, fitted with the basis
  double weight = 1.0;         // the coat's coverage
  double roughness = 0.0;      // the coat lobe's perceptual roughness
  double ior = 1.6;            // the coat's index: where the path inside it runs
  Rgb color{1.0, 1.0, 1.0};    // the round trip's tint at normal incidence
};

// The coat's tint over the round trip at cosine mu in air: color^(1 / mu_t) with mu_t the cosine
// inside the coat, written as the shaders do, exp2(log2(color) / mu_t) with 1 / mu_t =
// inversesqrt(1 - (1 - mu^2) / ior^2).
Rgb coat_tint(const CoatCoefficients& coat, double mu);

// F, Fbar or an area light's radiance of each lobe.
struct CoatedFresnel {
  Rgb base{};         // the base lobe's, the coat's attenuation and tint included
  double coat = 0.0;  // the coat lobe's, its weight included
  // Both lobes summed: what a mirror-like surface reflects, and matc eval's F and Fbar.
  Rgb total() const { return {base[0] + coat, base[1] + coat, base[2] + coat}; }
};

// The base lobe's F: mix(in_air, (1 - f)^2 v / (1 - f min(v, 1)), weight) per channel with f the
// coat's F clamped to [0, 1] and v >= 0 the under-coat F times the tint: transmitted into the
// coat, reflected by the metal and the coat's underside any number of times, transmitted out.
// v is not clamped at 1 where it multiplies (a colour outside the working space's gamut keeps
// its value, as uncoated curves do), only in the sum of the bounces, which it would make diverge.
inline Rgb layered_base(const Rgb& in_air, const Rgb& under_coat, const Rgb& tint, double coat,
                        double weight) {
  const double f = std::clamp(coat, 0.0, 1.0);
  Rgb result{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double v = std::max(under_coat[c], 0.0) * tint[c];
    const double through = (1.0 - f) * (1.0 - f) * v / std::max(1.0 - f * std::min(v, 1.0), 1e-6);
    result[c] = in_air[c] + weight * (through - in_air[c]);
  }
  return result;
}

// Both lobes' F for a direct light at mu = dot(V, H), with the shaders' basis.
CoatedFresnel evaluate_coated_fresnel(const Coefficients& in_air, const CoatCoefficients& coat,
                                      const ShaderBasis& basis, double mu);

// Both lobes' preintegrated F from the preintegrated basis at (NdotV, the base's roughness),
// `bbar`, and at (NdotV, the coat's roughness), `coat_bbar`: the base attenuated by the coat's
// preintegrated F (its directional albedo), tinted at NdotV. Any table: the LUT, the embedded
// one, the closed form.
CoatedFresnel evaluate_coated_preintegrated(const Coefficients& in_air,
                                            const CoatCoefficients& coat,
                                            const std::array<double, kBasisSize>& bbar,
                                            const std::array<double, kBasisSize>& coat_bbar,
                                            double ndotv);

// The same through `lut`: the base's at `roughness`, the coat's at its own.
CoatedFresnel evaluate_coated_fbar(const Coefficients& in_air, const CoatCoefficients& coat,
                                   const LutView& lut, double ndotv, double roughness);

// A polygon light of radiance 1 on both lobes, as matc_ltc_quad_light_<name> computes it (the
// total): each lobe's LTC integral (the table at its roughness) times its Fbar. Vertices in the
// shading frame (normal +z, view in the xz-plane), as polygon_light_ltc takes them.
CoatedFresnel polygon_light_ltc_coated(const Coefficients& in_air, const CoatCoefficients& coat,
                                       const LutView& lut, const LtcTableView& ltc, double ndotv,
                                       double roughness, std::span<const Vec3> vertices);

// A film under the coat (docs/thin-film.md): its table holds the base lobe, the film in air and
// under the coat layered at every node, and the coat lobe comes from the coat's coefficients as
// for a bare metal under it. F for a direct light at mu = dot(V, H) ...
CoatedFresnel evaluate_film_coated_fresnel(const FilmTable& table, const CoatCoefficients& coat,
                                           const ShaderBasis& basis, double mu);
// ... Fbar, the base's from the table at (NdotV, roughness), the coat's from `lut` at its own
// roughness ...
CoatedFresnel evaluate_film_coated_fbar(const FilmTable& table, const CoatCoefficients& coat,
                                        const LutView& lut, double ndotv, double roughness);
// ... and a polygon light of radiance 1, each lobe's LTC integral times its Fbar.
CoatedFresnel film_polygon_light_ltc_coated(const FilmTable& table, const CoatCoefficients& coat,
                                            const LutView& lut, const LtcTableView& ltc,
                                            double ndotv, double roughness,
                                            std::span<const Vec3> vertices);

// What reaches a layer under the coat and comes back through it as glTF layers a clear coat
// (KHR_materials_clearcoat), matc_coat_transmission_<name>: 1 - the coat lobe's F at NdotV, its
// weight included. glTF's metal-rough model under a matc coat scales the engine's dielectric,
// diffuse included, by it (metal_rough.h, docs/gltf.md).
double coat_transmission(const CoatCoefficients& coat, const ShaderBasis& basis, double ndotv);

}  // namespace matc::runtime
