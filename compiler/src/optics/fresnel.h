// Fresnel reflectance models over mu = cos(theta), the cosine between view (or light) and normal.
#pragma once

#include <complex>

namespace matc {

// Relative complex index of refraction eta = n + i k of the surface over the outside medium.
struct ComplexIor {
  double n = 1.0;
  double k = 0.0;
  std::complex<double> eta() const { return {n, k}; }
};

// Exact unpolarised Fresnel reflectance of a smooth interface (Born & Wolf; pbrt-v4 FrComplex).
// Stable for k -> 0 (dielectrics), n < 1 (total internal reflection) and mu -> 0 (returns 1).
double fresnel_exact(double mu, ComplexIor ior);

// The same reflectance in real arithmetic (the a^2 + b^2 form of pbrt-v3's FrConductor) for
// n > 0, k >= 0 at mu > 0: about five times faster than the complex form, for loops over tens of
// thousands of curves (`matc bake`); tests/unit/optics/optics_test.cpp checks the two agree.
double fresnel_conductor(double mu, ComplexIor ior);

// Reflectance at normal incidence, ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
double fresnel_normal_incidence(ComplexIor ior);

// Schlick 1994: F0 + (1 - F0)(1 - mu)^5.
double fresnel_schlick(double mu, double f0);

// Hoffman's F82-tint model (Kutz et al. 2021): Schlick minus a mu (1 - mu)^6, with `a` chosen so
// the curve passes through `f_at_mu_bar` at mu_bar = 1/7 (about 82 degrees).
inline constexpr double kF82MuBar = 1.0 / 7.0;
double fresnel_f82_tint(double mu, double f0, double f_at_mu_bar);

}  // namespace matc
