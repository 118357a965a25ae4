// The F82-tint look matched to an exact curve, what an OpenPBR material standing for it would
// use: F0 = F(1) and, per channel, tint = F(1/7) / Schlick(1/7) of the curve, at most 1. The
// accuracy table and the basis studies score each measured metal's.
#pragma once

#include <algorithm>
#include <cstddef>

#include "optics/fresnel.h"
#include "optics/reflectance_curve.h"

namespace matc::bench {

struct F82TintLook {
  Rgb f0{};
  Rgb tint{};
};

inline F82TintLook f82_tint_look(const ReflectanceCurve& exact) {
  F82TintLook look{exact.at(1.0), {}};
  const Rgb f82 = exact.at(kF82MuBar);
  for (std::size_t c = 0; c < 3; ++c)
    look.tint[c] = std::min(1.0, f82[c] / fresnel_schlick(kF82MuBar, look.f0[c]));
  return look;
}

}  // namespace matc::bench
