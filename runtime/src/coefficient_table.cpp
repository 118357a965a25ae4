#include "matc/runtime/coefficient_table.h"

#include <algorithm>
#include <cmath>

#include "matc/runtime/shipped_bases.h"
#include "texel_axis.h"

namespace matc::runtime {
double coefficient_table_u_from_reflectivity(double reflectivity) {
  const double r = unit_clamp(reflectivity);
  return 0.5 * (std::sqrt(std::sqrt(r)) + r * r);
}

double coefficient_table_reflectivity_from_u(double u) {
  // u = (q + q^8) / 2 with q = r^(1/4): Newton from q = 1, where the increasing convex function
  // is approached from above, so every step is monotone and the count is fixed.
  const double target = unit_clamp(u);
  double q = 1.0;
  for (int step = 0; step < 64; ++step) {
    const double q7 = q * q * q * q * q * q * q;
    const double next = q - (0.5 * (q + q7 * q) - target) / (0.5 + 4.0 * q7);
    if (!(next < q)) break;
    q = std::max(next, 0.0);
  }
  const double q2 = q * q;
  return q2 * q2;
}

double coefficient_table_v_from_edge_tint(double edge_tint) {
  return 1.0 - std::sqrt(1.0 - unit_clamp(edge_tint));
}

double coefficient_table_edge_tint_from_v(double v) {
  const double w = 1.0 - unit_clamp(v);
  return 1.0 - w * w;
}

std::array<float, kCoefficientTableChannels> CoefficientTableView::texel(std::size_t x,
                                                                         std::size_t y) const {
  const std::size_t offset = (y * size + x) * kCoefficientTableChannels;
  return {texels[offset], texels[offset + 1]};
}

std::array<double, kCoefficientTableChannels> sample_coefficient_table(
    const CoefficientTableView& table, double reflectivity, double edge_tint) {
  return sample_coefficient_table_at(table, coefficient_table_u_from_reflectivity(reflectivity),
                                     coefficient_table_v_from_edge_tint(edge_tint));
}

std::array<double, kCoefficientTableChannels> sample_coefficient_table_at(
    const CoefficientTableView& table, double u, double v) {
  return sample_bilinear<kCoefficientTableChannels>(table, table.size, u, v);
}

ChannelCoefficients channel_coefficients_from_table(const CoefficientTableView& table,
                                                    double reflectivity, double edge_tint) {
  const double r = unit_clamp(reflectivity);
  const auto sampled = sample_coefficient_table(table, r, edge_tint);
  return {r, 1.0 - r, sampled[0], sampled[1]};
}

Coefficients coefficients_from_table(const CoefficientTableView& table, const Rgb& reflectivity,
                                     const Rgb& edge_tint) {
  Coefficients coefficients{};
  for (std::size_t c = 0; c < 3; ++c)
    coefficients[c] = channel_coefficients_from_table(table, reflectivity[c], edge_tint[c]);
  return coefficients;
}

ArtisticRgb artistic_from_ior(const Rgb& n, const Rgb& k) {
  ArtisticRgb out;
  for (std::size_t c = 0; c < 3; ++c) {
    const double k2 = k[c] * k[c];
    const double r =
        unit_clamp(((n[c] - 1.0) * (n[c] - 1.0) + k2) / ((n[c] + 1.0) * (n[c] + 1.0) + k2));
    const double sqrt_r = std::sqrt(r);
    // n_max(r) - n over n_max(r) - n_min(r), both multiplied through by (1 - sqrt r)(1 + r) so
    // that r -> 1 stays finite: n_max = (1 + sqrt r) / (1 - sqrt r), n_min = (1 - r) / (1 + r).
    const double above = (1.0 + sqrt_r) * (1.0 + r) - n[c] * (1.0 - sqrt_r) * (1.0 + r);
    const double span = (1.0 + sqrt_r) * (1.0 + r) - (1.0 - r) * (1.0 - sqrt_r);
    out.reflectivity[c] = r;
    out.edge_tint[c] = span > 0.0 ? unit_clamp(above / span) : 0.0;
  }
  return out;
}

CoefficientTableView shipped_coefficient_table(BasisKind kind) {
  return shipped_basis_record(kind).coefficient_table();
}

}  // namespace matc::runtime
