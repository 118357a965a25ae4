// Where a bilinear sampler with texel centres on both ends of an axis reads (the tables' shared
// convention: texcoord = (u * (size - 1) + 0.5) / size, clamp to edge).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

namespace matc::runtime {

// x clamped to [0, 1], NaN read as 0: inputs come from textures and user data, and a NaN
// reaching a float-to-index conversion would be undefined behaviour.
inline double unit_clamp(double x) {
  return x >= 0.0 ? std::min(x, 1.0) : 0.0;
}

// Left texel index and blend weight along one axis for a coordinate u in [0, 1] (unit_clamp'ed).
inline std::pair<std::size_t, double> texel_axis_position(double u, std::size_t size) {
  const double position = unit_clamp(u) * static_cast<double>(size - 1);
  const std::size_t left = std::min(static_cast<std::size_t>(position), size - 2);
  return {left, position - static_cast<double>(left)};
}

// Bilinear filtering of a width x height table whose texel(x, y) returns Channels floats, at
// coordinates (u, v) in [0, 1] along both axes, exactly as a sampler with the convention above
// reads it.
template <std::size_t Channels, typename Table>
std::array<double, Channels> sample_bilinear(const Table& table, std::size_t width,
                                             std::size_t height, double u, double v) {
  const auto [x, tx] = texel_axis_position(u, width);
  const auto [y, ty] = texel_axis_position(v, height);
  const auto t00 = table.texel(x, y);
  const auto t10 = table.texel(x + 1, y);
  const auto t01 = table.texel(x, y + 1);
  const auto t11 = table.texel(x + 1, y + 1);
  std::array<double, Channels> result{};
  for (std::size_t i = 0; i < Channels; ++i) {
    const double bottom = t00[i] + tx * (t10[i] - t00[i]);
    const double top = t01[i] + tx * (t11[i] - t01[i]);
    result[i] = bottom + ty * (top - bottom);
  }
  return result;
}

// The same for a square table.
template <std::size_t Channels, typename Table>
std::array<double, Channels> sample_bilinear(const Table& table, std::size_t size, double u,
                                             double v) {
  return sample_bilinear<Channels>(table, size, size, u, v);
}

}  // namespace matc::runtime
