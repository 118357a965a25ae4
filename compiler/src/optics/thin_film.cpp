#include "optics/thin_film.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "optics/spectral.h"

namespace matc {
namespace {

using Complex = std::complex<double>;

// Amplitude reflection at the interface from a medium of index a (q_a = a cos theta_a) into one
// of index b, for s and p, with the same sign convention on every interface (so that the Airy sum
// of air/film and film/metal gives air/metal when the film vanishes).
struct Amplitudes {
  Complex s;
  Complex p;
};

Amplitudes interface(Complex a, Complex q_a, Complex b, Complex q_b) {
  return {(q_a - q_b) / (q_a + q_b), (b * b * q_a - a * a * q_b) / (b * b * q_a + a * a * q_b)};
}

}  // namespace

double thin_film_reflectance(double mu, double wavelength_nm, const ThinFilm& film,
                             ComplexIor metal) {
  const double cos0 = std::clamp(mu, 0.0, 1.0);
  const double sin2 = 1.0 - cos0 * cos0;
  const Complex n0 = 1.0, n1 = film.ior, n2 = metal.eta();
  const Complex q0 = cos0;
  const Complex q1 = std::sqrt(n1 * n1 - sin2);
  const Complex q2 = std::sqrt(n2 * n2 - sin2);
  const Amplitudes r01 = interface(n0, q0, n1, q1);
  const Amplitudes r12 = interface(n1, q1, n2, q2);
  const Complex phase =
      std::exp(Complex(0.0, 4.0 * std::numbers::pi * film.thickness_nm / wavelength_nm) * q1);
  const auto airy = [&](Complex first, Complex second) {
    return std::norm((first + second * phase) / (1.0 + first * second * phase));
  };
  return 0.5 * (airy(r01.s, r12.s) + airy(r01.p, r12.p));
}

ThinFilmCurve::ThinFilmCurve(const Spectrum& metal, const ThinFilm& film, ColorSpace space)
    : weights_(spectral_weights(space)), film_(film) {
  ior_.reserve(weights_.size());
  for (std::size_t i = 0; i < weights_.size(); ++i)
    ior_.push_back(metal.at(static_cast<double>(kCieFirstNm) + static_cast<double>(i)));
}

Rgb ThinFilmCurve::at(double mu) const {
  Rgb result{};
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    const double f = thin_film_reflectance(
        mu, static_cast<double>(kCieFirstNm) + static_cast<double>(i), film_, ior_[i]);
    for (std::size_t c = 0; c < 3; ++c)
      result[c] += weights_[i][c] * f;
  }
  return result;
}

}  // namespace matc
