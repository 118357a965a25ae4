// A Monte-Carlo reference for a metal under a rough coat (docs/coating.md): the directional albedo
// of the layered surface itself, with no split sum and no basis. Light paths cross the coat's
// microsurface (GGX, exact dielectric Fresnel, refraction, total internal reflection), lose to
// the coat's absorption along each leg (Beer's law), reflect off the metal's microsurface (GGX,
// the exact metal/coat Fresnel) and bounce between the two any number of times. Each microsurface
// scatters once (Smith's masking-shadowing, as the preintegrated table's GGX).
#pragma once

#include <cstddef>
#include <cstdint>

#include "material/material.h"
#include "optics/reflectance_curve.h"

namespace matc {

struct LayeredSurface {
  const ReflectanceCurve& in_air;         // the metal's exact curve in air (weight < 1)
  const ReflectanceCurve& metal_in_coat;  // the metal against the coat, at its own cosine
  CoatInput coat;
  double base_roughness = 0.0;  // perceptual; alpha = roughness^2
};

struct LayeredEstimate {
  Rgb mean{};
  Rgb standard_error{};
};

inline constexpr std::size_t kLayeredReferencePaths = 1u << 17;

// The split-sum layering with exact curves (no basis, no table): each lobe's exact curve
// preintegrated at its own roughness (`in_air` and `under_coat` at the base's, the coat's
// dielectric at the coat's) and combined as the shaders combine the table's values
// (runtime::layered_base). What the basis and the table cost, alone; `in_air` and `under_coat`
// are best tabulated (TabulatedCurve), since each call integrates them.
Rgb layered_split_sum(const ReflectanceCurve& in_air, const ReflectanceCurve& under_coat,
                      const CoatInput& coat, double ndotv, double base_roughness);

// The albedo seen from view cosine `ndotv`: (1 - weight) x the bare metal's + weight x the coated
// surface's, from `paths` light paths (a fixed seed: the same numbers every run).
LayeredEstimate layered_albedo(const LayeredSurface& surface, double ndotv,
                               std::size_t paths = kLayeredReferencePaths, std::uint64_t seed = 1);

}  // namespace matc
