// Training sets for the basis fit: the complex IORs whose exact Fresnel curves the SVDs see.
// Every set is a deterministic grid (strata midpoints) so that a refit reproduces the same bytes.
#pragma once

#include <cstddef>
#include <vector>

#include "optics/fresnel.h"

namespace matc {

// `count` dielectrics with eta evenly spread over [eta_min, eta_max].
std::vector<ComplexIor> dielectric_training_iors(std::size_t count, double eta_min, double eta_max);

// Gulbrandsen conductors on a reflectivity x edge-tint grid: r evenly spread over (0, r_max),
// g over (g_min, 1). One curve per grid cell.
struct ArtisticGrid {
  std::size_t reflectivity_steps = 0;
  std::size_t edge_tint_steps = 0;
  double reflectivity_max = 1.0;
  double edge_tint_min = 0.0;
};
std::vector<ComplexIor> artistic_training_iors(const ArtisticGrid& grid);

// Conductors on an (n, k) grid: n log-spaced over [n_min, n_max], k evenly over [k_min, k_max].
struct ComplexIorGrid {
  std::size_t n_steps = 0;
  std::size_t k_steps = 0;
  double n_min = 0.05;
  double n_max = 4.0;
  double k_min = 0.5;
  double k_max = 8.0;
};
std::vector<ComplexIor> complex_ior_training_iors(const ComplexIorGrid& grid);

}  // namespace matc
