// Where a bilinear sampler with texel centres on both ends of an axis reads (the tables' shared
// convention: texcoord = (u * (size - 1) + 0.5) / size, clamp to edge).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>

namespace matc::runtime {

// Left texel index and blend weight along one axis for a coordinate u in [0, 1] (clamped; NaN
// reads as 0, where a float-to-index conversion would be undefined).
inline std::pair<std::size_t, double> texel_axis_position(double u, std::size_t size) {
  const double position = (u >= 0.0 ? std::min(u, 1.0) : 0.0) * static_cast<double>(size - 1);
  const std::size_t left = std::min(static_cast<std::size_t>(position), size - 2);
  return {left, position - static_cast<double>(left)};
}

}  // namespace matc::runtime
