// The Gulbrandsen look matched to an exact curve, what an artist's r and g standing for a measured
// channel would be: r = the channel's F0 (at most `max_reflectivity`: Gulbrandsen's mapping has no
// conductor at r = 1), g the edge tint whose Gulbrandsen curve is closest to the channel's
// (largest difference over 201 cosines, searched to 1e-3). The coefficient-table study and the
// film-over-an-RGB-metal study score each measured metal's.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "optics/fresnel.h"
#include "optics/gulbrandsen.h"
#include "optics/reflectance_curve.h"

namespace matc::bench {

inline std::array<ArtisticParameters, 3> gulbrandsen_look(
    const ReflectanceCurve& curve,
    double max_reflectivity = std::numeric_limits<double>::infinity()) {
  std::array<ArtisticParameters, 3> out{};
  const Rgb f0 = curve.at(1.0);
  std::vector<Rgb> exact(201);
  for (std::size_t j = 0; j < exact.size(); ++j)
    exact[j] = curve.at(static_cast<double>(j) / 200.0);
  for (std::size_t c = 0; c < 3; ++c) {
    const double r = std::min(f0[c], max_reflectivity);
    const auto distance = [&](double g) {
      const ComplexIor ior = gulbrandsen_to_ior({r, g});
      double worst = 0.0;
      for (std::size_t j = 0; j < exact.size(); ++j)
        worst = std::max(
            worst, std::abs(fresnel_exact(static_cast<double>(j) / 200.0, ior) - exact[j][c]));
      return worst;
    };
    double best_g = 0.0, best = distance(0.0);
    for (int i = 1; i <= 1000; ++i) {
      const double d = distance(i / 1000.0);
      if (d < best) best = d, best_g = i / 1000.0;
    }
    out[c] = {r, best_g};
  }
  return out;
}

}  // namespace matc::bench
