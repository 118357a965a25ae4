#include "basis/training_set.h"

#include <cmath>

#include "optics/gulbrandsen.h"

namespace matc {
namespace {

double stratum_midpoint(std::size_t i, std::size_t count) {
  return (static_cast<double>(i) + 0.5) / static_cast<double>(count);
}

}  // namespace

std::vector<ComplexIor> dielectric_training_iors(std::size_t count, double eta_min,
                                                 double eta_max) {
  std::vector<ComplexIor> iors;
  for (std::size_t i = 0; i < count; ++i)
    iors.push_back({eta_min + stratum_midpoint(i, count) * (eta_max - eta_min), 0.0});
  return iors;
}

std::vector<ComplexIor> artistic_training_iors(const ArtisticGrid& grid) {
  std::vector<ComplexIor> iors;
  for (std::size_t i = 0; i < grid.reflectivity_steps; ++i) {
    const double r = stratum_midpoint(i, grid.reflectivity_steps) * grid.reflectivity_max;
    for (std::size_t j = 0; j < grid.edge_tint_steps; ++j) {
      const double g = grid.edge_tint_min +
                       stratum_midpoint(j, grid.edge_tint_steps) * (1.0 - grid.edge_tint_min);
      iors.push_back(gulbrandsen_to_ior({r, g}));
    }
  }
  return iors;
}

std::vector<ComplexIor> complex_ior_training_iors(const ComplexIorGrid& grid) {
  std::vector<ComplexIor> iors;
  const double log_ratio = std::log(grid.n_max / grid.n_min);
  for (std::size_t i = 0; i < grid.n_steps; ++i) {
    const double n = grid.n_min * std::exp(stratum_midpoint(i, grid.n_steps) * log_ratio);
    for (std::size_t j = 0; j < grid.k_steps; ++j)
      iors.push_back(
          {n, grid.k_min + stratum_midpoint(j, grid.k_steps) * (grid.k_max - grid.k_min)});
  }
  return iors;
}

}  // namespace matc
