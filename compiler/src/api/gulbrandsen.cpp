#include <cmath>

#include "checked_values.h"
#include "matc/api/compiled_material.h"
#include "optics/gulbrandsen.h"

namespace matc::api {

ComplexIor ior_from_artistic(const ArtisticParameters& artistic) {
  check_each(
      "reflectivity", artistic.reflectivity, [](double r) { return r >= 0.0 && r < 1.0; },
      "a number in [0, 1)");
  check_unit_interval("edge_tint", artistic.edge_tint);
  ComplexIor out;
  for (std::size_t c = 0; c < out.n.size(); ++c) {
    const matc::ComplexIor ior =
        gulbrandsen_to_ior({artistic.reflectivity[c], artistic.edge_tint[c]});
    out.n[c] = ior.n;
    out.k[c] = ior.k;
  }
  return out;
}

ArtisticParameters artistic_from_ior(const ComplexIor& ior) {
  check_each(
      "n", ior.n, [](double n) { return n > 0.0 && std::isfinite(n); }, "a finite number above 0");
  check_each(
      "k", ior.k, [](double k) { return k >= 0.0 && std::isfinite(k); },
      "a finite number, 0 or above");
  ArtisticParameters out;
  for (std::size_t c = 0; c < out.reflectivity.size(); ++c) {
    const matc::ArtisticParameters artistic = ior_to_gulbrandsen({ior.n[c], ior.k[c]});
    out.reflectivity[c] = artistic.reflectivity;
    out.edge_tint[c] = artistic.edge_tint;
  }
  return out;
}

}  // namespace matc::api
