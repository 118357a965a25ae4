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

double wavelength_at(std::size_t grid_index) {
  return static_cast<double>(kCieFirstNm) + static_cast<double>(grid_index);
}

// What the curves below need at one cosine, whatever the wavelength: the film's real q_1 (its
// index is real and at least 1, so n_1^2 - sin^2 > 0), the air/film amplitudes (real) and the
// phase's rate over 1 / lambda. thin_film_reflectance is the reference they are held to
// (thin_film_test); these save its complex square root, exponential and first interface per
// wavelength, which a compile evaluates at 2001 cosines x 471 wavelengths.
struct FilmAtCosine {
  double sin2 = 0.0;
  double q1 = 0.0;
  double n1_squared = 0.0;
  double r01_s = 0.0;
  double r01_p = 0.0;
  double phase_per_inverse_nm = 0.0;  // delta = this / lambda

  FilmAtCosine(double mu, const ThinFilm& film) {
    const double cos0 = std::clamp(mu, 0.0, 1.0);
    sin2 = 1.0 - cos0 * cos0;
    n1_squared = film.ior * film.ior;
    // n_1^2 - sin^2 as (n_1^2 - 1) + cos^2: near grazing, 1 - cos^2 rounds to 1 and a film of
    // index 1 would lose its q_1 = cos (and the Airy sum become 0 / 0). Callers check
    // is_propagating first.
    q1 = std::sqrt(std::max((n1_squared - 1.0) + cos0 * cos0, 0.0));
    r01_s = (cos0 - q1) / (cos0 + q1);
    r01_p = (n1_squared * cos0 - q1) / (n1_squared * cos0 + q1);
    phase_per_inverse_nm = 4.0 * std::numbers::pi * film.thickness_nm * q1;
  }

  // The film/metal amplitudes for the metal's eta^2. Divisions written out: std::complex's
  // guards against infinities (__divdc3) cost more than the rest of the sum, and no operand here
  // is infinite.
  Amplitudes metal_amplitudes(Complex eta_squared) const {
    const Complex q2 = principal_sqrt(eta_squared - sin2);
    const Complex eta_q1 = eta_squared * q1, n1_q2 = n1_squared * q2;
    return {quotient(q1 - q2, q1 + q2), quotient(eta_q1 - n1_q2, eta_q1 + n1_q2)};
  }

  // e^{i delta} at wavelength lambda.
  Complex phase(double wavelength_nm) const {
    const double delta = phase_per_inverse_nm / wavelength_nm;
    return {std::cos(delta), std::sin(delta)};
  }

  // Unpolarised reflectance of the film over a metal of amplitudes r12 at the phase of a
  // wavelength: |r01 + r12 e^{i delta}|^2 / |1 + r01 r12 e^{i delta}|^2 per polarisation.
  double reflectance(const Amplitudes& r12, Complex phase) const {
    return reflectance(r12, phase.real(), phase.imag());
  }
  // The same in real arithmetic, the phase as (cos delta, sin delta): no std::complex product
  // (its infinity guards) in the way of a loop over many phases being vectorised.
  double reflectance(const Amplitudes& r12, double phase_re, double phase_im) const {
    const auto airy = [&](double first, Complex second) {
      const double deeper_re = second.real() * phase_re - second.imag() * phase_im;
      const double deeper_im = second.real() * phase_im + second.imag() * phase_re;
      const double top_re = first + deeper_re;
      const double bottom_re = 1.0 + first * deeper_re, bottom_im = first * deeper_im;
      return (top_re * top_re + deeper_im * deeper_im) /
             (bottom_re * bottom_re + bottom_im * bottom_im);
    };
    return 0.5 * (airy(r01_s, r12.s) + airy(r01_p, r12.p));
  }

  // Whether the film's wave propagates at this cosine: always for a film of index >= 1; a film
  // under a coat of higher index (relative index below 1) is evanescent beyond its critical angle,
  // where q_1 is imaginary and thin_film_reflectance's complex sum holds instead.
  static bool is_propagating(double mu, const ThinFilm& film) {
    const double cos0 = std::clamp(mu, 0.0, 1.0);
    return (film.ior * film.ior - 1.0) + cos0 * cos0 >= 0.0;
  }

  static Complex quotient(Complex a, Complex b) { return a * std::conj(b) / std::norm(b); }

  // The root with a non-negative real part, as std::sqrt takes it, without csqrt's handling of
  // infinities and signed zeros (nothing here is infinite, and eta^2 - sin^2 is never -0).
  static Complex principal_sqrt(Complex z) {
    const double t = std::sqrt(0.5 * (std::sqrt(std::norm(z)) + std::abs(z.real())));
    if (t == 0.0) return 0.0;
    if (z.real() >= 0.0) return {t, z.imag() / (2.0 * t)};
    return {std::abs(z.imag()) / (2.0 * t), std::copysign(t, z.imag())};
  }
};

// weight x filmed + (1 - weight) x bare, as covered_reflectance.
double covered(const ThinFilm& film, double filmed, double mu, ComplexIor metal) {
  if (film.weight == 1.0) return filmed;
  return film.weight * filmed + (1.0 - film.weight) * fresnel_exact(mu, metal);
}

// e^{i delta} at thicknesses start + k step for one wavelength: delta is linear in the thickness,
// so each is the one before turned by e^{i rate step} (a complex product, not a sine and cosine).
struct SweepPhases {
  std::vector<double> re, im;
  explicit SweepPhases(std::size_t count) : re(count), im(count) {}
  void turn(double rate, double start_nm, double step_nm) {
    double phase_re = std::cos(rate * start_nm), phase_im = std::sin(rate * start_nm);
    const double turn_re = std::cos(rate * step_nm), turn_im = std::sin(rate * step_nm);
    for (std::size_t k = 0; k < re.size(); ++k) {
      re[k] = phase_re;
      im[k] = phase_im;
      const double next_re = phase_re * turn_re - phase_im * turn_im;
      phase_im = phase_re * turn_im + phase_im * turn_re;
      phase_re = next_re;
    }
  }
};

// A film of 1 nm: FilmAtCosine's phase rate is then per nanometre of thickness.
ThinFilm per_nanometre(const ThinFilm& film) {
  return {film.ior, 1.0, film.weight};
}

// What a sweep cannot turn phases for: grazing, where everything reflects, and a film whose wave
// does not propagate (a film under a coat past its critical angle: not reached from air), where
// each thickness is the curve's own sum. True when `out` is filled so.
template <typename Curve>
bool sweep_without_phases(const Curve& curve, const ThinFilm& film, double mu, double start_nm,
                          double step_nm, std::span<Rgb> out) {
  if (!(mu > 0.0)) {
    std::fill(out.begin(), out.end(), Rgb{1.0, 1.0, 1.0});
    return true;
  }
  if (FilmAtCosine::is_propagating(mu, film)) return false;
  for (std::size_t k = 0; k < out.size(); ++k)
    out[k] = curve.with_thickness(start_nm + step_nm * static_cast<double>(k)).at(mu);
  return true;
}

}  // namespace

ThinFilm film_under_coat(const ThinFilm& film, double ambient_ior) {
  return {film.ior / ambient_ior, film.thickness_nm * ambient_ior, film.weight};
}

double covered_reflectance(double mu, double wavelength_nm, const ThinFilm& film,
                           ComplexIor metal) {
  return covered(film, thin_film_reflectance(mu, wavelength_nm, film, metal), mu, metal);
}

double thin_film_reflectance(double mu, double wavelength_nm, const ThinFilm& film,
                             ComplexIor metal) {
  const double cos0 = std::clamp(mu, 0.0, 1.0);
  // At grazing every stack reflects everything; a film of index 1 would make it 0 / 0 below.
  if (cos0 == 0.0) return 1.0;
  const double sin2 = 1.0 - cos0 * cos0;
  const Complex n0 = 1.0, n1 = film.ior, n2 = metal.eta();
  const Complex q0 = cos0;
  const Complex q1 = std::sqrt((n1 * n1 - 1.0) + cos0 * cos0);  // as FilmAtCosine: exact near 0
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
    ior_.push_back(metal.at(wavelength_at(i)));
}

Rgb ThinFilmCurve::at(double mu) const {
  if (!(mu > 0.0)) return {1.0, 1.0, 1.0};  // grazing, as thin_film_reflectance (weights sum to 1)
  Rgb result{};
  if (!FilmAtCosine::is_propagating(mu, film_)) {
    for (std::size_t i = 0; i < weights_.size(); ++i) {
      const double f = covered_reflectance(mu, wavelength_at(i), film_, ior_[i]);
      for (std::size_t c = 0; c < 3; ++c)
        result[c] += weights_[i][c] * f;
    }
    return result;
  }
  const FilmAtCosine at_cosine(mu, film_);
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    const Complex eta = ior_[i].eta();
    const double filmed = at_cosine.reflectance(at_cosine.metal_amplitudes(eta * eta),
                                                at_cosine.phase(wavelength_at(i)));
    const double f = covered(film_, filmed, mu, ior_[i]);
    for (std::size_t c = 0; c < 3; ++c)
      result[c] += weights_[i][c] * f;
  }
  return result;
}

ThinFilmCurve ThinFilmCurve::with_thickness(double thickness_nm) const {
  ThinFilmCurve curve = *this;
  curve.film_.thickness_nm = thickness_nm;
  return curve;
}

void ThinFilmCurve::sweep_thickness(double mu, double start_nm, double step_nm,
                                    std::span<Rgb> out) const {
  if (sweep_without_phases(*this, film_, mu, start_nm, step_nm, out)) return;
  std::fill(out.begin(), out.end(), Rgb{});
  const FilmAtCosine at_cosine(mu, per_nanometre(film_));
  SweepPhases phases(out.size());
  std::vector<double> filmed(out.size());
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    const Complex eta = ior_[i].eta();
    const Amplitudes r12 = at_cosine.metal_amplitudes(eta * eta);
    const double bare = film_.weight == 1.0 ? 0.0 : fresnel_exact(mu, ior_[i]);
    phases.turn(at_cosine.phase_per_inverse_nm / wavelength_at(i), start_nm, step_nm);
    for (std::size_t k = 0; k < out.size(); ++k)
      filmed[k] = at_cosine.reflectance(r12, phases.re[k], phases.im[k]);
    for (std::size_t k = 0; k < out.size(); ++k) {
      const double f =
          film_.weight == 1.0 ? filmed[k] : film_.weight * filmed[k] + (1.0 - film_.weight) * bare;
      for (std::size_t c = 0; c < 3; ++c)
        out[k][c] += weights_[i][c] * f;
    }
  }
}

ThinFilmChannelCurve::ThinFilmChannelCurve(const std::array<ComplexIor, 3>& ior,
                                           const ThinFilm& film, ColorSpace space)
    : weights_(spectral_weights(space)), ior_(ior), film_(film) {}

Rgb ThinFilmChannelCurve::at(double mu) const {
  if (!(mu > 0.0)) return {1.0, 1.0, 1.0};  // grazing, as thin_film_reflectance
  if (!FilmAtCosine::is_propagating(mu, film_)) {
    Rgb result{};
    for (std::size_t i = 0; i < weights_.size(); ++i) {
      for (std::size_t c = 0; c < 3; ++c)
        result[c] += weights_[i][c] * covered_reflectance(mu, wavelength_at(i), film_, ior_[c]);
    }
    return result;
  }
  // One index a channel: its amplitudes, and its bare reflectance, hold for every wavelength, and
  // a wavelength's phase holds for every channel.
  const FilmAtCosine at_cosine(mu, film_);
  std::array<Amplitudes, 3> r12{};
  for (std::size_t c = 0; c < 3; ++c) {
    const Complex eta = ior_[c].eta();
    r12[c] = at_cosine.metal_amplitudes(eta * eta);
  }
  Rgb filmed{};
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    const Complex phase = at_cosine.phase(wavelength_at(i));
    for (std::size_t c = 0; c < 3; ++c)
      filmed[c] += weights_[i][c] * at_cosine.reflectance(r12[c], phase);
  }
  // The weights of a channel sum to 1, so the bare share is the channel's bare reflectance.
  Rgb result{};
  for (std::size_t c = 0; c < 3; ++c)
    result[c] = covered(film_, filmed[c], mu, ior_[c]);
  return result;
}

ThinFilmChannelCurve ThinFilmChannelCurve::with_thickness(double thickness_nm) const {
  ThinFilmChannelCurve curve = *this;
  curve.film_.thickness_nm = thickness_nm;
  return curve;
}

void ThinFilmChannelCurve::sweep_thickness(double mu, double start_nm, double step_nm,
                                           std::span<Rgb> out) const {
  if (sweep_without_phases(*this, film_, mu, start_nm, step_nm, out)) return;
  const FilmAtCosine at_cosine(mu, per_nanometre(film_));
  std::array<Amplitudes, 3> r12{};
  for (std::size_t c = 0; c < 3; ++c) {
    const Complex eta = ior_[c].eta();
    r12[c] = at_cosine.metal_amplitudes(eta * eta);
  }
  std::vector<Rgb> filmed(out.size(), Rgb{});
  SweepPhases phases(out.size());
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    phases.turn(at_cosine.phase_per_inverse_nm / wavelength_at(i), start_nm, step_nm);
    for (std::size_t c = 0; c < 3; ++c) {
      for (std::size_t k = 0; k < out.size(); ++k)
        filmed[k][c] += weights_[i][c] * at_cosine.reflectance(r12[c], phases.re[k], phases.im[k]);
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    for (std::size_t c = 0; c < 3; ++c)
      out[k][c] = covered(film_, filmed[k][c], mu, ior_[c]);
  }
}

}  // namespace matc
