// Three-vectors of doubles for the area-light code (directions and positions in the shading frame).
#pragma once

#include <array>
#include <cmath>

namespace matc::runtime {

using Vec3 = std::array<double, 3>;

inline Vec3 minus(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

inline Vec3 plus(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

inline Vec3 scaled(const Vec3& v, double s) {
  return {v[0] * s, v[1] * s, v[2] * s};
}

inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline double length(const Vec3& a) {
  return std::sqrt(dot(a, a));
}

inline Vec3 normalize(const Vec3& v) {
  const double l = length(v);
  return {v[0] / l, v[1] / l, v[2] / l};
}

}  // namespace matc::runtime
