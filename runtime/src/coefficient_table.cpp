#include "matc/runtime/coefficient_table.h"

#include <algorithm>
#include <cmath>

#include "texel_axis.h"

namespace matc::runtime {
double coefficient_table_u_from_reflectivity(double reflectivity) {
  return std::cbrt(unit_clamp(reflectivity));
}
double coefficient_table_reflectivity_from_u(double u) {
  return u * u * u;
}

double coefficient_table_v_from_edge_tint(double reflectivity, double edge_tint) {
  const double g = unit_clamp(edge_tint);
  const double delta = coefficient_table_ior_span(reflectivity);
  if (delta <= 0.0) return g;                    // r = 0: n_min = n_max = 1
  if (delta >= 1.0) return g < 1.0 ? 0.0 : 1.0;  // r = 1: n_max is infinite
  return std::log1p(-g * delta) / std::log1p(-delta);
}

double coefficient_table_edge_tint_from_v(double reflectivity, double v) {
  const double delta = coefficient_table_ior_span(reflectivity);
  if (delta <= 0.0 || delta >= 1.0) return v;
  return -std::expm1(v * std::log1p(-delta)) / delta;
}

double coefficient_table_ior_span(double reflectivity) {
  const double r = unit_clamp(reflectivity);
  return 2.0 * std::sqrt(r) / (1.0 + r);
}

std::array<float, kCoefficientTableChannels> CoefficientTableView::texel(std::size_t x,
                                                                         std::size_t y) const {
  const std::size_t offset = (y * size + x) * kCoefficientTableChannels;
  return {texels[offset], texels[offset + 1]};
}

std::array<double, kCoefficientTableChannels> sample_coefficient_table(
    const CoefficientTableView& table, double reflectivity, double edge_tint) {
  return sample_coefficient_table_at(table, coefficient_table_u_from_reflectivity(reflectivity),
                                     coefficient_table_v_from_edge_tint(reflectivity, edge_tint));
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
  switch (kind) {
    case BasisKind::paper:
      return paper_coefficient_table();
    case BasisKind::f82:
      return f82_coefficient_table();
    case BasisKind::powers:
      return powers_coefficient_table();
    case BasisKind::extended:
      break;
  }
  return extended_coefficient_table();
}

}  // namespace matc::runtime
