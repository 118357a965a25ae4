#include "optics/coat.h"

#include <algorithm>
#include <cmath>

namespace matc {

double refracted_cosine(double mu, double coat_ior) {
  const double sin2_inside = (1.0 - mu * mu) / (coat_ior * coat_ior);
  return std::sqrt(std::max(0.0, 1.0 - sin2_inside));
}

double coat_fresnel(double mu, double coat_ior) {
  return fresnel_exact(mu, {coat_ior, 0.0});
}

ComplexIor under_coat(ComplexIor metal, double coat_ior) {
  return {metal.n / coat_ior, metal.k / coat_ior};
}

double coat_round_trip_transmittance(double color, double mu_inside) {
  if (color >= 1.0) return 1.0;
  if (color <= 0.0) return 0.0;
  return std::pow(color, 1.0 / mu_inside);
}

double f0_seen_from_coat(double f0, double coat_ior) {
  const double s = std::sqrt(std::clamp(f0, 0.0, 0.999));
  const double n = (1.0 + s) / (1.0 - s);
  const double r = (n - coat_ior) / (n + coat_ior);
  return r * r;
}

double coated_base_reflectance(double coat_reflectance, double tinted_under_coat) {
  const double f = std::clamp(coat_reflectance, 0.0, 1.0);
  const double v = std::max(tinted_under_coat, 0.0);
  // A v above 1 (a colour outside the working space's gamut) keeps its value; only the sum of
  // the bounces, which it would make diverge, sees it clamped. 1 - f v is then 0 only at
  // f = v = 1, where the numerator's (1 - f)^2 is 0 too.
  const double bounces = std::max(1.0 - f * std::min(v, 1.0), 1e-12);
  return (1.0 - f) * (1.0 - f) * v / bounces;
}

Rgb UnderCoatCurve::at(double mu) const {
  return metal_in_coat_->at(refracted_cosine(mu, coat_ior_));
}

Rgb CoatCurve::at(double mu) const {
  const double f = coat_fresnel(mu, coat_ior_);
  return {f, f, f};
}

Rgb LayeredCurve::at(double mu) const {
  const double f = coat_fresnel(mu, coat_ior_);
  if (part_ == Part::coat) return {weight_ * f, weight_ * f, weight_ * f};
  const Rgb air = in_air_.at(mu);
  const Rgb under = under_coat_.at(mu);
  const double mu_inside = refracted_cosine(mu, coat_ior_);
  Rgb result{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double tinted = coat_round_trip_transmittance(color_[c], mu_inside) * under[c];
    const double base = (1.0 - weight_) * air[c] + weight_ * coated_base_reflectance(f, tinted);
    result[c] = part_ == Part::base ? base : weight_ * f + base;
  }
  return result;
}

}  // namespace matc
