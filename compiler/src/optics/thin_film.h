// A thin dielectric film over a conductor (issue #67: heat-tinted titanium, anodised metals): air,
// a film of real index n_f >= 1 and thickness d, then the metal of complex index eta. One film,
// coherent: the Airy sum of its internal reflections, s and p apart, averaged for unpolarised
// light. The metal's phase on reflection is kept (the engines' KHR_materials_iridescence takes the
// base for a dielectric and loses it). ../shared/notes/thin_film.md has the physics.
#pragma once

#include "optics/color_space.h"
#include "optics/fresnel.h"
#include "optics/reflectance_curve.h"
#include "optics/spectrum.h"

#include <array>
#include <span>
#include <vector>

namespace matc {

struct ThinFilm {
  // The film's real index relative to the medium the light comes from: >= 1 in air; under a coat
  // (film_under_coat) it may be below 1, and the film's wave is then evanescent beyond the critical
  // angle.
  double ior = 1.5;
  double thickness_nm = 0.0;  // 0: no film (the bare metal exactly)
  double weight = 1.0;        // coverage: the curves below mix the bare metal's F by 1 - weight
};

// The same film seen from inside a medium of index `ambient_ior` (a coat): every index relative to
// the coat's, and the thickness scaled by it so that the phase, 4 pi d q_1 / lambda with q_1 in
// absolute terms, is kept. With the metal's index divided by `ambient_ior` too (under_coat), the
// functions below then give the film's reflectance at the cosine inside the coat.
ThinFilm film_under_coat(const ThinFilm& film, double ambient_ior);

// Unpolarised reflectance at cosine mu in air (clamped to [0, 1]) and wavelength `wavelength_nm`:
//   r = (r01 + r12 e^{i delta}) / (1 + r01 r12 e^{i delta}),   delta = 4 pi d q_1 / lambda
// per polarisation, with q_j = n_j cos(theta_j) = sqrt(n_j^2 - sin^2 theta_0) (principal root: the
// wave decays into the metal). A film of thickness 0, or of index 1, gives fresnel_exact(mu, eta).
double thin_film_reflectance(double mu, double wavelength_nm, const ThinFilm& film,
                             ComplexIor metal);

// The same with the film's coverage: weight x the film's reflectance + (1 - weight) x the bare
// metal's (fresnel_exact).
double covered_reflectance(double mu, double wavelength_nm, const ThinFilm& film, ComplexIor metal);

// The same film at many thicknesses at once: what a thickness per pixel's stack tabulates
// (compile/film_tables.h). Each wavelength's amplitudes are found once a cosine, and its phase,
// linear in the thickness, turns by one rotation a step: a stack's rows cost a few complex
// products a wavelength instead of a film's whole sum each.
class ThinFilmSweep {
 public:
  virtual ~ThinFilmSweep() = default;
  // F at cosine mu of the film at thicknesses start_nm + k step_nm, for k < out.size(); the
  // film's own thickness is not used. Within 1e-12 of at() of each film (the rotations' rounding).
  virtual void sweep_thickness(double mu, double start_nm, double step_nm,
                               std::span<Rgb> out) const = 0;
};

// The film over a spectral metal, per wavelength, reduced to RGB as SpectralCurve reduces the bare
// metal (CIE 1931 2-degree observer under D65 into the working space).
class ThinFilmCurve final : public ReflectanceCurve, public ThinFilmSweep {
 public:
  ThinFilmCurve(const Spectrum& metal, const ThinFilm& film, ColorSpace space = kDefaultColorSpace);
  Rgb at(double mu) const override;
  // The same metal under the same film of another thickness.
  ThinFilmCurve with_thickness(double thickness_nm) const;
  void sweep_thickness(double mu, double start_nm, double step_nm,
                       std::span<Rgb> out) const override;

 private:
  const std::vector<Rgb>& weights_;
  std::vector<ComplexIor> ior_;  // the metal on the integration grid
  ThinFilm film_;
};

// The film over a metal known by one complex index per channel (an RGB material: Gulbrandsen's
// r and g, n and k, F82-tint's stand-in conductor), in `space`: each channel's Airy sum at every
// wavelength of the integration grid with that channel's index, weighted as ThinFilmCurve weights
// that channel. Summing over the band, rather than taking one wavelength a channel, averages the
// film's fringes as the spectral reduction does (docs/accuracy.md, "A film over an RGB metal").
// A film of 0 nm gives fresnel_exact per channel (the weights of a channel sum to 1).
class ThinFilmChannelCurve final : public ReflectanceCurve, public ThinFilmSweep {
 public:
  ThinFilmChannelCurve(const std::array<ComplexIor, 3>& ior, const ThinFilm& film,
                       ColorSpace space);
  Rgb at(double mu) const override;
  ThinFilmChannelCurve with_thickness(double thickness_nm) const;
  void sweep_thickness(double mu, double start_nm, double step_nm,
                       std::span<Rgb> out) const override;

 private:
  const std::vector<Rgb>& weights_;
  std::array<ComplexIor, 3> ior_;
  ThinFilm film_;
};

}  // namespace matc
