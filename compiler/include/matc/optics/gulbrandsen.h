// Gulbrandsen 2014, "Artist Friendly Metallic Fresnel" (JCGT 3(4)): reflectivity r (normal
// incidence reflectance) and edge tint g map to a complex IOR whose exact Fresnel curve has F(1) =
// r.
#pragma once

#include "matc/optics/fresnel.h"

namespace matc {

struct ArtisticParameters {
  double reflectivity = 0.0;  // r in [0, 1)
  double edge_tint = 0.0;     // g in [0, 1]
};

// r, g -> n, k. g = 1 gives the smallest n for r (n_min), g = 0 the largest (n_max, k = 0).
ComplexIor gulbrandsen_to_ior(ArtisticParameters parameters);

// n, k -> r, g: the inverse mapping. g leaves [0, 1] for an IOR no (r, g) in range produces.
ArtisticParameters ior_to_gulbrandsen(ComplexIor ior);

}  // namespace matc
