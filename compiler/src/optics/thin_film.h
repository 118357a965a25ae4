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

#include <vector>

namespace matc {

struct ThinFilm {
  double ior = 1.5;           // the film's real index, >= 1
  double thickness_nm = 0.0;  // 0: no film (the bare metal exactly)
};

// Unpolarised reflectance at cosine mu in air (clamped to [0, 1]) and wavelength `wavelength_nm`:
//   r = (r01 + r12 e^{i delta}) / (1 + r01 r12 e^{i delta}),   delta = 4 pi d q_1 / lambda
// per polarisation, with q_j = n_j cos(theta_j) = sqrt(n_j^2 - sin^2 theta_0) (principal root: the
// wave decays into the metal). A film of thickness 0, or of index 1, gives fresnel_exact(mu, eta).
double thin_film_reflectance(double mu, double wavelength_nm, const ThinFilm& film,
                             ComplexIor metal);

// The film over a spectral metal, per wavelength, reduced to RGB as SpectralCurve reduces the bare
// metal (CIE 1931 2-degree observer under D65 into the working space).
class ThinFilmCurve final : public ReflectanceCurve {
 public:
  ThinFilmCurve(const Spectrum& metal, const ThinFilm& film, ColorSpace space = kDefaultColorSpace);
  Rgb at(double mu) const override;

 private:
  const std::vector<Rgb>& weights_;
  std::vector<ComplexIor> ior_;  // the metal on the integration grid
  ThinFilm film_;
};

}  // namespace matc
