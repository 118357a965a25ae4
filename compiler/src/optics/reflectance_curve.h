// An exact RGB Fresnel curve F_c(mu): what the decomposition is fitted to and measured against.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "matc/runtime/fresnel.h"
#include "optics/color_space.h"
#include "optics/fresnel.h"

namespace matc {

using runtime::Rgb;

class ReflectanceCurve {
 public:
  virtual ~ReflectanceCurve() = default;
  // Reflectance per channel of the working space at mu = cos(theta) in [0, 1].
  virtual Rgb at(double mu) const = 0;
  // F at mu = 0 where it is not 1: conductors and dielectrics seen from air reach 1 at grazing
  // (the coefficient solves pin c_1 = 1 - c_0 for them); a metal seen through a coat does not.
  virtual std::optional<Rgb> grazing_value() const { return std::nullopt; }
};

// One complex IOR per channel (from an `ior` or `artistic` material).
class IorCurve final : public ReflectanceCurve {
 public:
  explicit IorCurve(std::array<ComplexIor, 3> ior) : ior_(ior) {}
  Rgb at(double mu) const override;
  const std::array<ComplexIor, 3>& ior() const { return ior_; }

 private:
  std::array<ComplexIor, 3> ior_;
};

// The OpenPBR / Adobe Standard Material metal (Kutz et al. 2021): per channel F82-tint with F0 =
// `f0` and F(1/7) = `tint` x Schlick(1/7), from an `f82_tint` material.
class F82TintCurve final : public ReflectanceCurve {
 public:
  F82TintCurve(const Rgb& f0, const Rgb& tint) : f0_(f0), tint_(tint) {}
  Rgb at(double mu) const override;

 private:
  Rgb f0_;
  Rgb tint_;
};

// Another curve with a 3x3 matrix applied to its RGB: a change of working space, or a gamut
// mapping (both linear, so the result is still a curve the basis fits like any other).
class TransformedCurve final : public ReflectanceCurve {
 public:
  TransformedCurve(std::unique_ptr<ReflectanceCurve> curve, const Matrix3& matrix)
      : curve_(std::move(curve)), matrix_(matrix) {}
  Rgb at(double mu) const override { return multiply(matrix_, curve_->at(mu)); }
  std::optional<Rgb> grazing_value() const override {
    const auto inner = curve_->grazing_value();
    if (!inner) return std::nullopt;
    return multiply(matrix_, *inner);
  }

 private:
  std::unique_ptr<ReflectanceCurve> curve_;
  Matrix3 matrix_;
};

}  // namespace matc
