#include <cmath>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "matc/api/compiled_material.h"
#include "optics/gulbrandsen.h"

namespace matc::api {
namespace {

void check_channels(std::string_view field, const Rgb& values, bool (*allowed)(double),
                    std::string_view takes) {
  for (std::size_t c = 0; c < values.size(); ++c) {
    if (!allowed(values[c]))
      throw std::invalid_argument(
          fmt::format("{}: element {} is {}; {}", field, c, values[c], takes));
  }
}

}  // namespace

ComplexIor ior_from_artistic(const ArtisticParameters& artistic) {
  check_channels(
      "reflectivity", artistic.reflectivity, [](double r) { return r >= 0.0 && r < 1.0; },
      "a number in [0, 1)");
  check_channels(
      "edge_tint", artistic.edge_tint, [](double g) { return g >= 0.0 && g <= 1.0; },
      "a number in [0, 1]");
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
  check_channels(
      "n", ior.n, [](double n) { return n > 0.0 && std::isfinite(n); }, "a finite number above 0");
  check_channels(
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
