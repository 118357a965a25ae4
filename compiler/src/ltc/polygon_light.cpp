#include "ltc/polygon_light.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace matc {
namespace {

using runtime::cross;
using runtime::dot;
using runtime::length;
using runtime::minus;

// Relative tolerances, against the polygon's size: what double-precision input can state.
constexpr double kPlanarTolerance = 1e-6;
constexpr double kAreaTolerance = 1e-12;
// Larger coordinates overflow the checks below (Newell's normal squares products of two
// coordinates) long before any light could need them.
constexpr double kMaxCoordinate = 1e30;

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(trim(text.substr(start, end - start)));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return parts;
}

}  // namespace

PolygonLightParse parse_polygon_light(std::string_view text, std::size_t vertex_count) {
  const std::vector<std::string_view> vertices = split(text, ';');
  if (vertices.size() != vertex_count) {
    return {{},
            fmt::format("expected {} vertices \"x,y,z\" separated by ';', got {}", vertex_count,
                        vertices.size())};
  }
  PolygonLightParse result;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const std::vector<std::string_view> coordinates = split(vertices[v], ',');
    if (coordinates.size() != 3) {
      return {{},
              fmt::format("vertex {} (\"{}\"): expected 3 numbers x,y,z, got {}", v + 1,
                          vertices[v], coordinates.size())};
    }
    Vec3 vertex{};
    for (std::size_t c = 0; c < 3; ++c) {
      const std::string_view number = coordinates[c];
      const auto [end, error] =
          std::from_chars(number.data(), number.data() + number.size(), vertex[c]);
      if (error != std::errc() || end != number.data() + number.size() || number.empty()) {
        return {{}, fmt::format("vertex {}: \"{}\" is not a number", v + 1, number)};
      }
    }
    result.vertices.push_back(vertex);
  }
  result.error = check_polygon_light(result.vertices);
  if (!result.error.empty()) result.vertices.clear();
  return result;
}

std::string check_polygon_light(std::span<const Vec3> vertices) {
  const std::size_t n = vertices.size();
  if (n < 3) return fmt::format("a polygon needs at least 3 vertices, got {}", n);
  for (std::size_t v = 0; v < n; ++v) {
    for (const double c : vertices[v])
      if (!std::isfinite(c)) return fmt::format("vertex {}: coordinates must be finite", v + 1);
    for (const double c : vertices[v])
      if (std::abs(c) > kMaxCoordinate)
        return fmt::format(
            "vertex {}: coordinate {:g} is beyond {:g}, more than the light's arithmetic can hold "
            "(its areas would overflow); scale the light down",
            v + 1, c, kMaxCoordinate);
  }
  double size = 0.0;
  for (std::size_t v = 0; v < n; ++v)
    size = std::max(size, length(minus(vertices[v], vertices[(v + 1) % n])));
  for (std::size_t v = 0; v < n; ++v) {
    if (length(minus(vertices[v], vertices[(v + 1) % n])) <= kPlanarTolerance * size)
      return fmt::format("vertices {} and {} coincide: the polygon is degenerate", v + 1,
                         (v + 1) % n + 1);
  }
  // Newell's normal: twice the vector area, for any planar polygon.
  Vec3 normal{};
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3 c = cross(vertices[v], vertices[(v + 1) % n]);
    for (std::size_t k = 0; k < 3; ++k)
      normal[k] += c[k];
  }
  const double twice_area = length(normal);
  if (size == 0.0 || twice_area <= kAreaTolerance * size * size)
    return "the polygon has no net area (its vertices are collinear, or its outline crosses "
           "itself): it is degenerate";
  const Vec3 unit{normal[0] / twice_area, normal[1] / twice_area, normal[2] / twice_area};
  const double offset = dot(unit, vertices[0]);
  for (std::size_t v = 1; v < n; ++v) {
    const double distance = std::abs(dot(unit, vertices[v]) - offset);
    if (distance > kPlanarTolerance * size)
      return fmt::format(
          "the polygon is not planar: vertex {} lies {:.3g} off the plane of the others (at most "
          "{:.3g}, 1e-6 of its size)",
          v + 1, distance, kPlanarTolerance * size);
  }
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3 turn = cross(minus(vertices[(v + 1) % n], vertices[v]),
                            minus(vertices[(v + 2) % n], vertices[(v + 1) % n]));
    if (dot(turn, unit) <= 0.0)
      return fmt::format(
          "the polygon is not convex at vertex {} (or its vertices are not in order around it)",
          (v + 1) % n + 1);
  }
  if (std::abs(offset) <= kPlanarTolerance * size)
    return "the shading point lies in the light's plane: it sees the light edge-on";
  if (std::all_of(vertices.begin(), vertices.end(), [](const Vec3& p) { return p[2] <= 0.0; }))
    return "the light is entirely below the horizon (every vertex has z <= 0): it cannot light "
           "the surface";
  return {};
}

std::array<Vec3, 4> facing_square(const Vec3& direction, double distance, double half_size) {
  const Vec3 w = runtime::normalize(direction);
  // u horizontal (in the xz-plane) unless w is nearly vertical, v = w x u.
  const Vec3 u =
      std::abs(w[1]) < 0.9 ? runtime::normalize({w[2], 0.0, -w[0]}) : Vec3{1.0, 0.0, 0.0};
  const Vec3 v = cross(w, u);
  std::array<Vec3, 4> square{};
  constexpr std::array<std::array<double, 2>, 4> kCorners = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t k = 0; k < 3; ++k)
      square[i][k] = distance * w[k] + half_size * (kCorners[i][0] * u[k] + kCorners[i][1] * v[k]);
  }
  return square;
}

}  // namespace matc
