#include "optics/fresnel.h"

#include <algorithm>
#include <cmath>

namespace matc {

double fresnel_exact(double mu, ComplexIor ior) {
  const double cos_i = std::clamp(mu, 0.0, 1.0);
  // At grazing incidence both amplitudes tend to magnitude 1 for any eta != 1; the formula below
  // would divide 0 by 0 when cos_t also vanishes (n < 1, k = 0), so return the limit directly.
  if (cos_i == 0.0) return 1.0;
  const std::complex<double> eta = ior.eta();
  const double sin2_i = 1.0 - cos_i * cos_i;
  // Snell's law with a complex index; the principal square root keeps |r| <= 1 and is continuous
  // as k -> 0+, including beyond the critical angle when n < 1.
  const std::complex<double> cos_t = std::sqrt(1.0 - sin2_i / (eta * eta));
  const std::complex<double> r_parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const std::complex<double> r_perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5 * (std::norm(r_parallel) + std::norm(r_perpendicular));
}

double fresnel_conductor(double mu, ComplexIor ior) {
  const double cos_i = std::clamp(mu, 0.0, 1.0);
  if (cos_i == 0.0) return 1.0;
  const double cos2 = cos_i * cos_i, sin2 = 1.0 - cos2;
  const double n2 = ior.n * ior.n, k2 = ior.k * ior.k;
  // eta^2 - sin^2 = (a + i b)^2 (the transmitted wave's complex cosine times eta).
  const double t0 = n2 - k2 - sin2;
  const double a2_plus_b2 = std::sqrt(t0 * t0 + 4.0 * n2 * k2);
  // a^2 = (|eta^2 - sin^2| + t0) / 2; where t0 < 0 that sum cancels (a weakly absorbing index
  // below 1 past its critical angle), so use its equal 2 n^2 k^2 / (|...| - t0) there.
  const double a2 = t0 >= 0.0 ? 0.5 * (a2_plus_b2 + t0) : 2.0 * n2 * k2 / (a2_plus_b2 - t0);
  const double a = std::sqrt(std::max(0.0, a2));
  const double t1 = a2_plus_b2 + cos2, t2 = 2.0 * cos_i * a;
  const double r_perpendicular = (t1 - t2) / (t1 + t2);
  const double t3 = cos2 * a2_plus_b2 + sin2 * sin2, t4 = t2 * sin2;
  const double r_parallel = r_perpendicular * (t3 - t4) / (t3 + t4);
  return 0.5 * (r_parallel + r_perpendicular);
}

double fresnel_normal_incidence(ComplexIor ior) {
  const double k2 = ior.k * ior.k;
  return ((ior.n - 1.0) * (ior.n - 1.0) + k2) / ((ior.n + 1.0) * (ior.n + 1.0) + k2);
}

double fresnel_schlick(double mu, double f0) {
  const double m = 1.0 - std::clamp(mu, 0.0, 1.0);
  const double m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

namespace {

double f82_lobe(double x) {
  return x * std::pow(1.0 - x, 6.0);
}

}  // namespace

double fresnel_f82_tint(double mu, double f0, double f_at_mu_bar) {
  static const double lobe_at_mu_bar = f82_lobe(kF82MuBar);  // the same value, computed once
  const double a = (fresnel_schlick(kF82MuBar, f0) - f_at_mu_bar) / lobe_at_mu_bar;
  return fresnel_schlick(mu, f0) - a * f82_lobe(std::clamp(mu, 0.0, 1.0));
}

}  // namespace matc
