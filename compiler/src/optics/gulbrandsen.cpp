#include "matc/optics/gulbrandsen.h"

#include <algorithm>
#include <cmath>

namespace matc {
namespace {

double n_min(double r) {
  return (1.0 - r) / (1.0 + r);
}
double n_max(double r) {
  const double sqrt_r = std::sqrt(r);
  return (1.0 + sqrt_r) / (1.0 - sqrt_r);
}

}  // namespace

ComplexIor gulbrandsen_to_ior(ArtisticParameters parameters) {
  const double r = parameters.reflectivity;
  const double g = parameters.edge_tint;
  const double n = g * n_min(r) + (1.0 - g) * n_max(r);
  // The radicand is zero at g = 0 and can round slightly negative there.
  const double k2 = (r * (n + 1.0) * (n + 1.0) - (n - 1.0) * (n - 1.0)) / (1.0 - r);
  return {n, std::sqrt(std::max(0.0, k2))};
}

ArtisticParameters ior_to_gulbrandsen(ComplexIor ior) {
  const double r = fresnel_normal_incidence(ior);
  const double span = n_max(r) - n_min(r);
  // r = 0 (n = 1, k = 0) makes every g equivalent; report g = 0 rather than 0/0.
  const double g = span > 0.0 ? (n_max(r) - ior.n) / span : 0.0;
  return {r, g};
}

}  // namespace matc
