// A polygonal area light as matc's tools take it: vertices in the shading frame (normal +z, view
// in the xz-plane towards +x), relative to the shading point, either winding, two-sided,
// radiance 1. Checked once at the edge so that integrators never meet a degenerate polygon.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "matc/runtime/ltc.h"

namespace matc {

using runtime::Vec3;

struct PolygonLightParse {
  std::vector<Vec3> vertices;
  std::string error;  // empty when the polygon is usable
};

// "x,y,z;x,y,z;x,y,z;x,y,z" (spaces allowed), exactly `vertex_count` vertices, then
// check_polygon_light.
PolygonLightParse parse_polygon_light(std::string_view text, std::size_t vertex_count);

// Empty when the vertices form a light the integrators handle, else what is wrong: a
// non-finite coordinate, coincident vertices or (almost) no area, vertices off one plane,
// a non-convex or self-intersecting outline, the shading point in the light's plane, or every
// vertex at or below the horizon.
std::string check_polygon_light(std::span<const Vec3> vertices);

// A square light of half-size `half_size` centred at `distance` along `direction` (any length),
// facing the shading point, corners in order: the test lights of the fit's quality report and
// the area-light study.
std::array<Vec3, 4> facing_square(const Vec3& direction, double distance, double half_size);

}  // namespace matc
