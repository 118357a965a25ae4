#include "matc/runtime/ltc.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "texel_axis.h"

namespace matc::runtime {
namespace {

// The arc integral from a to b (unit vectors): theta * normalize(a x b), theta = angle(a, b)
// through atan2, which stays accurate for short and near-opposite arcs.
Vec3 edge_integral(const Vec3& a, const Vec3& b) {
  const Vec3 normal = cross(a, b);
  const double sine = std::sqrt(dot(normal, normal));
  const double theta = std::atan2(sine, dot(a, b));
  return sine > 0.0 ? scaled(normal, theta / sine) : Vec3{};
}

// Where the segment from a (above the horizon) to b (on or below it) meets z = 0, as a unit
// vector: the arc between their directions meets the horizon on the same ray.
Vec3 horizon_crossing(const Vec3& a, const Vec3& b) {
  const double t = a[2] / (a[2] - b[2]);
  return normalize({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), 0.0});
}

}  // namespace

std::array<float, kLtcChannels> LtcTableView::texel(std::size_t x, std::size_t y) const {
  const std::size_t offset = (y * size + x) * kLtcChannels;
  return {texels[offset], texels[offset + 1], texels[offset + 2], texels[offset + 3]};
}

double ltc_u_from_ndotv(double ndotv, LtcViewAxis axis) {
  if (axis == LtcViewAxis::sqrt_ndotv) return lut_u_from_ndotv(ndotv);
  return 1.0 - std::sqrt(1.0 - std::clamp(ndotv, 0.0, 1.0));
}

double ltc_ndotv_from_u(double u, LtcViewAxis axis) {
  if (axis == LtcViewAxis::sqrt_ndotv) return lut_ndotv_from_u(u);
  const double from_normal = 1.0 - u;
  return 1.0 - from_normal * from_normal;
}

LtcInverse sample_ltc(const LtcTableView& table, double ndotv, double roughness) {
  const auto m = sample_bilinear<kLtcChannels>(
      table, table.size, ltc_u_from_ndotv(ndotv, table.view_axis), unit_clamp(roughness));
  return {m[0], m[1], m[2], m[3]};
}

Vec3 clipped_polygon_vector_form_factor(std::span<const Vec3> vertices) {
  // Each edge integrated where it is above the horizon; a convex polygon that crosses the horizon
  // leaves it once and comes back once, and the horizon arc between those points closes it.
  Vec3 sum{};
  Vec3 exit{}, entry{};
  bool exits = false, enters = false;
  const std::size_t count = vertices.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3& a = vertices[i];
    const Vec3& b = vertices[(i + 1) % count];
    const bool a_above = a[2] > 0.0;
    const bool b_above = b[2] > 0.0;
    if (a_above && b_above) {
      sum = plus(sum, edge_integral(normalize(a), normalize(b)));
    } else if (a_above) {
      exit = horizon_crossing(a, b);
      exits = true;
      sum = plus(sum, edge_integral(normalize(a), exit));
    } else if (b_above) {
      entry = horizon_crossing(b, a);
      enters = true;
      sum = plus(sum, edge_integral(entry, normalize(b)));
    }
  }
  if (exits && enters) sum = plus(sum, edge_integral(exit, entry));
  // Either winding: oriented so that z, the form factor, is not negative.
  const double sign = sum[2] < 0.0 ? -1.0 : 1.0;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return {sign * sum[0] / kTwoPi, sign * sum[1] / kTwoPi, std::abs(sum[2]) / kTwoPi};
}

double clipped_polygon_form_factor(std::span<const Vec3> vertices) {
  return std::min(1.0, clipped_polygon_vector_form_factor(vertices)[2]);
}

Vec3 ltc_polygon_vector_form_factor(const LtcInverse& inverse, std::span<const Vec3> vertices) {
  std::array<Vec3, kMaxLightPolygonVertices> transformed{};
  const std::size_t count = std::min(vertices.size(), transformed.size());
  for (std::size_t i = 0; i < count; ++i)
    transformed[i] = inverse.apply(vertices[i]);
  return clipped_polygon_vector_form_factor({transformed.data(), count});
}

double ltc_polygon_integral(const LtcInverse& inverse, std::span<const Vec3> vertices) {
  return std::min(1.0, ltc_polygon_vector_form_factor(inverse, vertices)[2]);
}

std::array<Vec3, kDiskLightSides> disk_light_polygon(const Vec3& centre, const Vec3& normal,
                                                     double radius) {
  // An orthonormal basis around the normal (Duff et al. 2017), then the polygon whose area is the
  // disk's: circumradius r sqrt(2 pi / (n sin(2 pi / n))).
  const Vec3 n = normalize(normal);
  const double sign = std::copysign(1.0, n[2]);
  const double a = -1.0 / (sign + n[2]);
  const double b = n[0] * n[1] * a;
  const Vec3 tangent{1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0]};
  const Vec3 bitangent{b, sign + n[1] * n[1] * a, -n[1]};
  constexpr double kSides = static_cast<double>(kDiskLightSides);
  const double circumradius =
      radius *
      std::sqrt(2.0 * std::numbers::pi / (kSides * std::sin(2.0 * std::numbers::pi / kSides)));
  std::array<Vec3, kDiskLightSides> polygon{};
  for (std::size_t i = 0; i < kDiskLightSides; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / kSides;
    const double x = circumradius * std::cos(angle);
    const double y = circumradius * std::sin(angle);
    for (std::size_t k = 0; k < 3; ++k)
      polygon[i][k] = centre[k] + x * tangent[k] + y * bitangent[k];
  }
  return polygon;
}

std::array<Vec3, kDiskLightSides> sphere_light_polygon(const Vec3& point, const Vec3& centre,
                                                       double radius) {
  const Vec3 towards = minus(point, centre);
  const double distance = length(towards);
  const double disk_radius =
      radius * distance / std::sqrt(std::max(distance * distance - radius * radius, 1e-30));
  return disk_light_polygon(centre, towards, disk_radius);
}

namespace {

// A preintegrated Fresnel times the LTC integral of the polygon: what the shaders compute.
Rgb scaled_by_ltc_integral(Rgb fbar, const LtcTableView& ltc, double ndotv, double roughness,
                           std::span<const Vec3> vertices) {
  const double integral = ltc_polygon_integral(sample_ltc(ltc, ndotv, roughness), vertices);
  for (double& channel : fbar)
    channel *= integral;
  return fbar;
}

}  // namespace

Rgb polygon_light_ltc(const Coefficients& coefficients, const LutView& lut, const LtcTableView& ltc,
                      double ndotv, double roughness, std::span<const Vec3> vertices) {
  return scaled_by_ltc_integral(evaluate_fbar(coefficients, lut, ndotv, roughness), ltc, ndotv,
                                roughness, vertices);
}

Rgb film_polygon_light_ltc(const FilmTable& table, const LtcTableView& ltc, double ndotv,
                           double roughness, std::span<const Vec3> vertices) {
  return scaled_by_ltc_integral(film_preintegrated(table, ndotv, roughness), ltc, ndotv, roughness,
                                vertices);
}

}  // namespace matc::runtime
