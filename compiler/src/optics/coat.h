// A dielectric coat over a metal (docs/coating.md): the coat's own Fresnel, the directions inside
// it, its tint, and the reflectance of the layered pair for smooth interfaces.
#pragma once

#include <memory>

#include "optics/fresnel.h"
#include "optics/reflectance_curve.h"

namespace matc {

// The cosine inside a coat of index `coat_ior` of a direction at cosine `mu` in air (Snell). It
// runs from sqrt(1 - 1 / coat_ior^2) at grazing (0.75 for 1.5) to 1: the only part of the
// metal/coat curve a coated metal shows.
double refracted_cosine(double mu, double coat_ior);

// The coat's own reflectance at cosine `mu` in air: the exact dielectric Fresnel.
double coat_fresnel(double mu, double coat_ior);

// The metal's index relative to the coat it sits under, (n + i k) / coat_ior.
ComplexIor under_coat(ComplexIor metal, double coat_ior);

// What the coat lets through over the round trip down to the metal and back, for a path at
// cosine `mu_inside` in it: `color` (the round trip at normal incidence) to the power 1 /
// mu_inside, since each leg's length grows as 1 / mu_inside (Beer's law).
double coat_round_trip_transmittance(double color, double mu_inside);

// The base as seen from air through the coat, smooth interfaces: transmitted in (1 - F_coat),
// reflected by the metal and tinted over the round trip (`tinted_under_coat`, V), reflected back
// down by the coat's underside (F_coat again, by reciprocity) any number of times, and
// transmitted out: (1 - F_coat)^2 V / (1 - F_coat min(V, 1)). The coat's own reflection is not
// included.
double coated_base_reflectance(double coat_reflectance, double tinted_under_coat);

// F0 of a conductor seen from inside a coat of index `coat_ior` as engines convert it, with
// nothing but F0: read as a dielectric's index, then its reflectance against the coat (Filament's
// f0ClearCoatToSurface is a fit of this for 1.5). The edge tint is lost: Schlick's curve of it is
// the engines' stand-in for the metal under the coat.
double f0_seen_from_coat(double f0, double coat_ior);

// The metal seen through the coat at cosine mu in air, without the interfaces' transmission or
// the coat's tint: V(mu) = F_metal/coat(mu_t) with mu_t = refracted_cosine(mu). What a coated
// material's under-coat coefficients are fitted to (the tint, color^(1 / mu_t), varies over the
// whole range of mu, which a basis made for Fresnel curves does not follow: the shaders compute
// it). `metal_in_coat` is the metal's curve with its index relative to the coat, at its own
// cosine.
class UnderCoatCurve final : public ReflectanceCurve {
 public:
  UnderCoatCurve(std::unique_ptr<ReflectanceCurve> metal_in_coat, double coat_ior)
      : metal_in_coat_(std::move(metal_in_coat)), coat_ior_(coat_ior) {}
  Rgb at(double mu) const override;
  // V at grazing is the metal/coat curve at the critical cosine, not 1.
  std::optional<Rgb> grazing_value() const override { return at(0.0); }

 private:
  std::unique_ptr<ReflectanceCurve> metal_in_coat_;
  double coat_ior_;
};

// The coat's dielectric Fresnel in every channel.
class CoatCurve final : public ReflectanceCurve {
 public:
  explicit CoatCurve(double coat_ior) : coat_ior_(coat_ior) {}
  Rgb at(double mu) const override;

 private:
  double coat_ior_;
};

// The whole coated surface's reflectance with smooth interfaces, exact at both: the coat's lobe
// w F_coat plus the base, mix(in air, through the coat, w), the coat's tint over the path at
// each angle. `in_air` and `under_coat` are the exact curves (the latter an UnderCoatCurve's
// values); both must outlive this.
class LayeredCurve final : public ReflectanceCurve {
 public:
  // Both lobes, or one: the split-sum reference integrates each over its own roughness.
  enum class Part { both, base, coat };
  LayeredCurve(const ReflectanceCurve& in_air, const ReflectanceCurve& under_coat, double weight,
               double coat_ior, const Rgb& color, Part part = Part::both)
      : in_air_(in_air),
        under_coat_(under_coat),
        weight_(weight),
        coat_ior_(coat_ior),
        color_(color),
        part_(part) {}
  Rgb at(double mu) const override;

 private:
  const ReflectanceCurve& in_air_;
  const ReflectanceCurve& under_coat_;
  double weight_;
  double coat_ior_;
  Rgb color_;
  Part part_;
};

}  // namespace matc
