#include "lut/microfacet_samples.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace matc {
namespace {

double radical_inverse_base2(std::uint32_t bits) {
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return static_cast<double>(bits) * 0x1p-32;
}

// Smith's Lambda for GGX at a direction with cosine `cos_theta` to the normal.
float smith_lambda(float cos_theta, float alpha2) {
  const float cos2 = cos_theta * cos_theta;
  return 0.5f * (-1.0f + std::sqrt(1.0f + alpha2 * (1.0f - cos2) / cos2));
}

}  // namespace

HammersleySet::HammersleySet(std::size_t count) : disk_x_(count), disk_y_(count) {
  for (std::size_t k = 0; k < count; ++k) {
    const double u1 = (static_cast<double>(k) + 0.5) / static_cast<double>(count);
    const double phi =
        2.0 * std::numbers::pi * radical_inverse_base2(static_cast<std::uint32_t>(k));
    disk_x_[k] = static_cast<float>(std::sqrt(u1) * std::cos(phi));
    disk_y_[k] = static_cast<float>(std::sqrt(u1) * std::sin(phi));
  }
}

// Cloned for AVX2 with run-time dispatch; both clones compute the same IEEE results (no FMA
// contraction in ISO C++ mode), so the table does not depend on the machine that bakes it.
// tests/unit/lut/sampler_clones_test.cpp builds this file without clones and checks that claim.
#ifndef MATC_NO_TARGET_CLONES
__attribute__((target_clones("avx2", "default")))
#endif
void sample_microfacet_reflections(
    const HammersleySet& set, double ndotv, double roughness, float* vdoth, float* weight) {
  const double mu = std::clamp(ndotv, kMinIntegratedNdotV, 1.0);
  const auto alpha = static_cast<float>(roughness * roughness);
  const float alpha2 = alpha * alpha;
  // V = (sin, 0, cos) in the tangent frame. Heitz 2018: stretch V to the hemisphere configuration.
  const auto view_x = static_cast<float>(std::sqrt(1.0 - mu * mu));
  const auto view_z = static_cast<float>(mu);
  const float stretched_length = std::sqrt(alpha * view_x * alpha * view_x + view_z * view_z);
  const float vh_x = alpha * view_x / stretched_length;
  const float vh_z = view_z / stretched_length;
  // With V in the xz-plane the orthonormal frame around Vh is T1 = (0, 1, 0), T2 = (-vh_z, 0,
  // vh_x).
  const float blend = 0.5f * (1.0f + vh_z);
  const float lambda_v = smith_lambda(view_z, alpha2);

  const float* disk_x = set.disk_x();
  const float* disk_y = set.disk_y();
  const std::size_t count = set.size();
  // Branch-free so that the compiler vectorises it.
  for (std::size_t k = 0; k < count; ++k) {
    const float t1 = disk_x[k];
    const float t2 = (1.0f - blend) * std::sqrt(1.0f - t1 * t1) + blend * disk_y[k];
    const float t3 = std::sqrt(std::max(0.0f, 1.0f - t1 * t1 - t2 * t2));
    // Hemisphere normal in the stretched space, then unstretched back to the GGX microfacet normal.
    const float nh_x = -t2 * vh_z + t3 * vh_x;
    const float nh_y = t1;
    const float nh_z = t2 * vh_x + t3 * vh_z;
    const float h_x = alpha * nh_x;
    const float h_y = alpha * nh_y;
    const float h_z = std::max(0.0f, nh_z);
    const float inverse_length = 1.0f / std::sqrt(h_x * h_x + h_y * h_y + h_z * h_z);
    const float v_dot_h = (view_x * h_x + view_z * h_z) * inverse_length;
    const float light_z = 2.0f * v_dot_h * h_z * inverse_length - view_z;
    const float safe_light_z = std::max(light_z, 1e-7f);
    const float lambda_l = smith_lambda(safe_light_z, alpha2);
    const float g2_over_g1 = (1.0f + lambda_v) / (1.0f + lambda_v + lambda_l);
    vdoth[k] = std::min(std::max(v_dot_h, 0.0f), 1.0f);
    weight[k] = light_z > 0.0f ? g2_over_g1 : 0.0f;
  }
}

}  // namespace matc
