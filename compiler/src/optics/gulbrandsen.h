// Gulbrandsen 2014, "Artist Friendly Metallic Fresnel" (JCGT 3(4)): reflectivity r (normal
// incidence reflectance) and edge tint g map to a complex IOR whose exact Fresnel curve has F(1) =
// r.
#pragma once

#include "optics/fresnel.h"

namespace matc {

struct ArtisticParameters {
  double reflectivity = 0.0;  // r in [0, 1)
  double edge_tint = 0.0;     // g in [0, 1]
};

// r, g -> n, k. g = 1 gives the smallest n for r (n_min), g = 0 the largest (n_max, k = 0).
ComplexIor gulbrandsen_to_ior(ArtisticParameters parameters);

// n, k -> r, g: the inverse mapping. g leaves [0, 1] for an IOR no (r, g) in range produces.
ArtisticParameters ior_to_gulbrandsen(ComplexIor ior);

// The conductor with reflectance `f0` at normal incidence whose exact curve passes closest to
// `f_at_mu_bar` at mu = 1/7 (the Gulbrandsen edge tint, searched in [0, 1]; f0 is held below 1):
// an index for an F82-tint metal, which has none, where one is needed (under a coat).
ComplexIor conductor_matching_f82(double f0, double f_at_mu_bar);

}  // namespace matc
