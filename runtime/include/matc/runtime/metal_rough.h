// glTF's metal-rough model per pixel (docs/gltf.md), as the shaders' matc_metal_rough and
// matc_dielectric_fresnel compute it: glTF's BRDF mixes its dielectric and metal BRDFs by
// metalness (metallicFactor times the metallic-roughness texture's blue channel), and matc's
// Fresnel replaces the metal's only.
#pragma once

#include <algorithm>
#include <cmath>

#include "matc/runtime/fresnel.h"

namespace matc::runtime {

// mix(dielectric, metal, metalness) per channel, metalness clamped to [0, 1] (NaN reads as 0):
// the same term of each lobe (F for a light, the preintegrated F for image light).
inline Rgb metal_rough(const Rgb& dielectric, const Rgb& metal, double metalness) {
  const double m = metalness > 0 ? std::min(metalness, 1.0) : 0.0;
  Rgb mixed{};
  for (std::size_t c = 0; c < 3; ++c)
    mixed[c] = dielectric[c] + (metal[c] - dielectric[c]) * m;
  return mixed;
}

// The same under a matc coat, as matc_metal_rough_<name> computes it: the dielectric times the
// coat's transmission at NdotV (coat_transmission in coat.h: glTF's layering of a clear coat),
// mixed with the coated material's base lobe, `base` (the metal through the coat). The coat lobe
// lies over both, whatever the metalness.
inline Rgb metal_rough_under_coat(const Rgb& dielectric, const Rgb& base, double metalness,
                                  double transmission) {
  Rgb layered{};
  for (std::size_t c = 0; c < 3; ++c)
    layered[c] = dielectric[c] * transmission;
  return metal_rough(layered, base, metalness);
}

// glTF's dielectric Fresnel: Schlick's curve from f0 to f90 at the cosine mu (clamped to [0, 1]);
// f0 0.04 and f90 1 at glTF's index 1.5.
inline Rgb dielectric_fresnel(const Rgb& f0, const Rgb& f90, double mu) {
  const double m = 1.0 - std::clamp(mu, 0.0, 1.0);
  const double m5 = m * m * m * m * m;
  Rgb f{};
  for (std::size_t c = 0; c < 3; ++c)
    f[c] = f0[c] + (f90[c] - f0[c]) * m5;
  return f;
}

// glTF's default dielectric (index 1.5): F0 ((1.5 - 1) / (1.5 + 1))^2 = 0.04, F90 1.
inline constexpr double kGltfDielectricF0 = 0.04;

}  // namespace matc::runtime
