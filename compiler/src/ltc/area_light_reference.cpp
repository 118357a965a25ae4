#include "ltc/area_light_reference.h"

#include "base/rgb_mean.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace matc {
namespace {

using runtime::cross;
using runtime::dot;
using runtime::minus;

// A convex planar polygon as a fan of triangles from its first vertex, for uniform area sampling
// and for ray hits.
class ConvexPolygon {
 public:
  explicit ConvexPolygon(std::span<const Vec3> vertices)
      : vertices_(vertices.begin(), vertices.end()) {
    Vec3 normal{};
    for (std::size_t i = 1; i + 1 < vertices_.size(); ++i) {
      const Vec3 c =
          cross(minus(vertices_[i], vertices_[0]), minus(vertices_[i + 1], vertices_[0]));
      const double area = 0.5 * std::sqrt(dot(c, c));
      area_ += area;
      cumulative_.push_back(area_);
      for (std::size_t k = 0; k < 3; ++k)
        normal[k] += c[k];
    }
    const double length = std::sqrt(dot(normal, normal));
    normal_ = {normal[0] / length, normal[1] / length, normal[2] / length};
  }

  double area() const { return area_; }
  const Vec3& normal() const { return normal_; }

  // A uniformly distributed point for three numbers in [0, 1).
  Vec3 sample(double pick, double u1, double u2) const {
    const double target = pick * area_;
    std::size_t t = 0;
    while (t + 1 < cumulative_.size() && cumulative_[t] < target)
      ++t;
    const double s = std::sqrt(u1);
    const double b0 = 1.0 - s, b1 = s * (1.0 - u2), b2 = s * u2;
    const Vec3& a = vertices_[0];
    const Vec3& b = vertices_[t + 1];
    const Vec3& c = vertices_[t + 2];
    return {b0 * a[0] + b1 * b[0] + b2 * c[0], b0 * a[1] + b1 * b[1] + b2 * c[1],
            b0 * a[2] + b1 * b[2] + b2 * c[2]};
  }

  // The distance along the unit direction from the origin to the polygon, or 0 for a miss.
  double hit_distance(const Vec3& direction) const {
    const double along = dot(normal_, direction);
    if (along == 0.0) return 0.0;
    const double t = dot(normal_, vertices_[0]) / along;
    if (t <= 0.0) return 0.0;
    const Vec3 p{t * direction[0], t * direction[1], t * direction[2]};
    // Inside a convex polygon: on the same side of every edge as its normal says.
    const std::size_t n = vertices_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 edge = minus(vertices_[(i + 1) % n], vertices_[i]);
      if (dot(cross(edge, minus(p, vertices_[i])), normal_) < 0.0) return 0.0;
    }
    return t;
  }

 private:
  std::vector<Vec3> vertices_;
  std::vector<double> cumulative_;
  double area_ = 0.0;
  Vec3 normal_{};
};

}  // namespace

AreaLightEstimate integrate_polygon_light(const GgxLobe& lobe, std::span<const Vec3> vertices,
                                          const FresnelAtCosine& fresnel, std::size_t samples,
                                          std::uint64_t seed) {
  const ConvexPolygon polygon(vertices);
  // mt19937_64 is fully specified, and so is this conversion to [0, 1): the same numbers
  // everywhere (std::uniform_real_distribution is not).
  std::mt19937_64 random(seed);
  const auto uniform = [&] { return static_cast<double>(random() >> 11) * 0x1p-53; };
  // The light's density over solid angle in direction L at distance t.
  const auto light_pdf = [&](const Vec3& l, double t) {
    return t * t / (polygon.area() * std::abs(dot(polygon.normal(), l)));
  };
  RgbMean estimate;
  for (std::size_t k = 0; k < samples; ++k) {
    runtime::Rgb value{};
    // One direction's share, f F cos / (p_light + p_lobe): the balance heuristic.
    const auto add = [&](const Vec3& l, double distance) {
      const GgxLobe::Value lobe_value = lobe.evaluate(l);
      if (lobe_value.lobe <= 0.0) return;
      const double weight = lobe_value.lobe / (light_pdf(l, distance) + lobe_value.pdf);
      const runtime::Rgb f = fresnel(lobe_value.vdoth);
      for (std::size_t c = 0; c < 3; ++c)
        value[c] += weight * f[c];
    };
    // From the light's area, then from the lobe.
    // Drawn in sequence: the order in which a call's arguments are evaluated is unspecified
    // (GCC went right to left, Clang left to right). This is the order GCC's build drew them in,
    // which the published numbers come from.
    const double u_triangle_v = uniform();
    const double u_triangle_u = uniform();
    const double pick = uniform();
    const Vec3 p = polygon.sample(pick, u_triangle_u, u_triangle_v);
    const double t = std::sqrt(dot(p, p));
    add({p[0] / t, p[1] / t, p[2] / t}, t);
    const double u1 = uniform(), u2 = uniform();
    const Vec3 l = lobe.sample(u1, u2);
    if (const double hit = polygon.hit_distance(l); hit > 0.0) add(l, hit);
    estimate.add(value);
  }
  return {estimate.mean(), estimate.standard_error()};
}

}  // namespace matc
