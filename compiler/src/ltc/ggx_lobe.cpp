#include "ltc/ggx_lobe.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace matc {

GgxLobe::GgxLobe(double ndotv, double roughness)
    : alpha_(std::max(roughness * roughness, kMinLobeAlpha)) {
  const double mu = std::clamp(ndotv, kMinLobeNdotV, 1.0);
  view_ = {std::sqrt(1.0 - mu * mu), 0.0, mu};
  lambda_view_ = lambda(mu);
}

double GgxLobe::lambda(double cos_theta) const {
  const double cos2 = cos_theta * cos_theta;
  return 0.5 * (-1.0 + std::sqrt(1.0 + alpha_ * alpha_ * (1.0 - cos2) / cos2));
}

GgxLobe::Value GgxLobe::evaluate(const Vec3& light) const {
  if (light[2] <= 0.0) return {};
  Vec3 half{light[0] + view_[0], light[1] + view_[1], light[2] + view_[2]};
  const double length = std::sqrt(half[0] * half[0] + half[1] * half[1] + half[2] * half[2]);
  if (length <= 0.0) return {};
  for (double& h : half)
    h /= length;
  const double vdoth = std::max(0.0, view_[0] * half[0] + view_[2] * half[2]);
  // GGX: D = alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2).
  const double a2 = alpha_ * alpha_;
  const double denominator = half[2] * half[2] * (a2 - 1.0) + 1.0;
  const double distribution = a2 / (std::numbers::pi * denominator * denominator);
  const double g2 = 1.0 / (1.0 + lambda_view_ + lambda(light[2]));
  const double g1 = 1.0 / (1.0 + lambda_view_);
  // f cos(L) = D G2 / (4 cos(V)); visible-normal sampling: pdf = G1 D / (4 cos(V)).
  const double quarter = 1.0 / (4.0 * view_[2]);
  return {distribution * g2 * quarter, distribution * g1 * quarter, vdoth};
}

Vec3 GgxLobe::sample(double u1, double u2) const {
  // Heitz 2018: stretch V to the hemisphere configuration, sample the projected disk, unstretch.
  const Vec3 stretched = [&] {
    const Vec3 v{alpha_ * view_[0], 0.0, view_[2]};
    const double length = std::sqrt(v[0] * v[0] + v[2] * v[2]);
    return Vec3{v[0] / length, 0.0, v[2] / length};
  }();
  const double radius = std::sqrt(u1);
  const double phi = 2.0 * std::numbers::pi * u2;
  const double t1 = radius * std::cos(phi);
  const double blend = 0.5 * (1.0 + stretched[2]);
  const double t2 =
      (1.0 - blend) * std::sqrt(std::max(0.0, 1.0 - t1 * t1)) + blend * radius * std::sin(phi);
  const double t3 = std::sqrt(std::max(0.0, 1.0 - t1 * t1 - t2 * t2));
  // Frame around the stretched view: T1 = (0, 1, 0), T2 = (-vz, 0, vx).
  const Vec3 normal{-t2 * stretched[2] + t3 * stretched[0], t1,
                    t2 * stretched[0] + t3 * stretched[2]};
  Vec3 half{alpha_ * normal[0], alpha_ * normal[1], std::max(0.0, normal[2])};
  const double length = std::sqrt(half[0] * half[0] + half[1] * half[1] + half[2] * half[2]);
  for (double& h : half)
    h /= length;
  const double vdoth = view_[0] * half[0] + view_[2] * half[2];
  return {2.0 * vdoth * half[0] - view_[0], 2.0 * vdoth * half[1],
          2.0 * vdoth * half[2] - view_[2]};
}

double GgxLobe::albedo(std::size_t samples_per_axis) const {
  const auto n = static_cast<double>(samples_per_axis);
  double sum = 0.0;
  for (std::size_t j = 0; j < samples_per_axis; ++j) {
    for (std::size_t i = 0; i < samples_per_axis; ++i) {
      const Value value =
          evaluate(sample((static_cast<double>(i) + 0.5) / n, (static_cast<double>(j) + 0.5) / n));
      sum += value.pdf > 0.0 ? value.lobe / value.pdf : 0.0;
    }
  }
  return sum / (n * n);
}

}  // namespace matc
