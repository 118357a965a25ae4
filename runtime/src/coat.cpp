#include "matc/runtime/coat.h"

#include <cmath>

namespace matc::runtime {
namespace {

double coat_sum(const ChannelCoefficients& coat, const std::array<double, kBasisSize>& values) {
  double sum = 0.0;
  for (std::size_t i = 0; i < kBasisSize; ++i)
    sum += coat[i] * values[i];
  return std::max(0.0, sum);
}

// The coat lobe's F, its weight included, from the coat's sum (coat_sum).
double coat_lobe(const CoatCoefficients& coat, double sum) {
  return coat.weight * std::min(sum, 1.0);
}

}  // namespace

Rgb coat_tint(const CoatCoefficients& coat, double mu) {
  const double x = std::clamp(mu, 0.0, 1.0);
  const double inverse_square = 1.0 / (coat.ior * coat.ior);
  const double inverse_mu_inside = 1.0 / std::sqrt(1.0 - inverse_square * (1.0 - x * x));
  Rgb tint{};
  for (std::size_t c = 0; c < 3; ++c)
    tint[c] = coat.color[c] >= 1.0
                  ? 1.0
                  : std::exp2(std::log2(std::max(coat.color[c], 1e-30)) * inverse_mu_inside);
  return tint;
}

CoatedFresnel evaluate_coated_fresnel(const Coefficients& in_air, const CoatCoefficients& coat,
                                      const ShaderBasis& basis, double mu) {
  const auto b = evaluate_shader_basis(basis, mu);
  const double f = coat_sum(coat.coat, b);
  return {layered_base(combine(in_air, b), combine(coat.under_coat, b), coat_tint(coat, mu), f,
                       coat.weight),
          coat_lobe(coat, f)};
}

double coat_transmission(const CoatCoefficients& coat, const ShaderBasis& basis, double ndotv) {
  return 1.0 - coat_lobe(coat, coat_sum(coat.coat, evaluate_shader_basis(basis, ndotv)));
}

CoatedFresnel evaluate_coated_fbar(const Coefficients& in_air, const CoatCoefficients& coat,
                                   const LutView& lut, double ndotv, double roughness) {
  return evaluate_coated_preintegrated(in_air, coat, sample_lut(lut, ndotv, roughness),
                                       sample_lut(lut, ndotv, coat.roughness), ndotv);
}

CoatedFresnel evaluate_coated_preintegrated(const Coefficients& in_air,
                                            const CoatCoefficients& coat,
                                            const std::array<double, kBasisSize>& base,
                                            const std::array<double, kBasisSize>& coat_bbar,
                                            double ndotv) {
  const double f = coat_sum(coat.coat, coat_bbar);
  return {layered_base(combine(in_air, base), combine(coat.under_coat, base),
                       coat_tint(coat, ndotv), f, coat.weight),
          coat_lobe(coat, f)};
}

namespace {

// Each lobe's Fbar times its LTC integral, the table read at its roughness.
CoatedFresnel lit_by_polygon(const CoatedFresnel& lobes, const CoatCoefficients& coat,
                             const LtcTableView& ltc, double ndotv, double roughness,
                             std::span<const Vec3> vertices) {
  const double base = ltc_polygon_integral(sample_ltc(ltc, ndotv, roughness), vertices);
  const double coat_lobe = ltc_polygon_integral(sample_ltc(ltc, ndotv, coat.roughness), vertices);
  CoatedFresnel radiance{.coat = coat_lobe * lobes.coat};
  for (std::size_t c = 0; c < 3; ++c)
    radiance.base[c] = base * lobes.base[c];
  return radiance;
}

}  // namespace

CoatedFresnel polygon_light_ltc_coated(const Coefficients& in_air, const CoatCoefficients& coat,
                                       const LutView& lut, const LtcTableView& ltc, double ndotv,
                                       double roughness, std::span<const Vec3> vertices) {
  return lit_by_polygon(evaluate_coated_fbar(in_air, coat, lut, ndotv, roughness), coat, ltc, ndotv,
                        roughness, vertices);
}

CoatedFresnel evaluate_film_coated_fresnel(const FilmTable& table, const CoatCoefficients& coat,
                                           const ShaderBasis& basis, double mu) {
  return {film_fresnel(table, mu),
          coat_lobe(coat, coat_sum(coat.coat, evaluate_shader_basis(basis, mu)))};
}

CoatedFresnel evaluate_film_coated_fbar(const FilmTable& table, const CoatCoefficients& coat,
                                        const LutView& lut, double ndotv, double roughness) {
  return {film_preintegrated(table, ndotv, roughness),
          coat_lobe(coat, coat_sum(coat.coat, sample_lut(lut, ndotv, coat.roughness)))};
}

CoatedFresnel film_polygon_light_ltc_coated(const FilmTable& table, const CoatCoefficients& coat,
                                            const LutView& lut, const LtcTableView& ltc,
                                            double ndotv, double roughness,
                                            std::span<const Vec3> vertices) {
  return lit_by_polygon(evaluate_film_coated_fbar(table, coat, lut, ndotv, roughness), coat, ltc,
                        ndotv, roughness, vertices);
}

}  // namespace matc::runtime
