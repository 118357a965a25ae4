#include "optics/gulbrandsen.h"

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

ComplexIor conductor_matching_f82(double f0, double f_at_mu_bar) {
  const double r = std::clamp(f0, 0.0, 0.999);
  const auto miss = [&](double g) {
    const double f = fresnel_exact(kF82MuBar, gulbrandsen_to_ior({r, g}));
    return std::abs(f - f_at_mu_bar);
  };
  // Golden-section search: F(1/7) grows with the edge tint, so the miss has one minimum.
  constexpr double kInverseGolden = 0.6180339887498949;
  double low = 0.0, high = 1.0;
  for (int i = 0; i < 80; ++i) {
    const double a = high - kInverseGolden * (high - low);
    const double b = low + kInverseGolden * (high - low);
    if (miss(a) <= miss(b))
      high = b;
    else
      low = a;
  }
  return gulbrandsen_to_ior({r, 0.5 * (low + high)});
}

}  // namespace matc
