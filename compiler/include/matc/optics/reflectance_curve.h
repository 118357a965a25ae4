// An exact RGB Fresnel curve F_c(mu): what the decomposition is fitted to and measured against.
#pragma once

#include <array>

#include "matc/optics/fresnel.h"
#include "matc/runtime/fresnel.h"

namespace matc {

using runtime::Rgb;

class ReflectanceCurve {
 public:
  virtual ~ReflectanceCurve() = default;
  // Reflectance per linear-sRGB channel at mu = cos(theta) in [0, 1].
  virtual Rgb at(double mu) const = 0;
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

}  // namespace matc
