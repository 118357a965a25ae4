// Reflectance curves outside [0, 1] in a working space, and the gamut mapping offered for engines
// that clamp colours to that range (docs/color-spaces.md).
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "optics/color_space.h"
#include "optics/reflectance_curve.h"

namespace matc {

// Rounding in the matrices leaves white a few 1e-16 from 1: not a colour out of range.
inline constexpr double kGamutTolerance = 1e-9;

// The smallest and largest value each channel takes over mu in [0, 1].
struct CurveRange {
  Rgb min{};
  Rgb max{};
  bool within_unit_range() const;  // within kGamutTolerance
};

// Measured at `samples` cosines uniform in [0, 1] (the ends included).
CurveRange measure_curve_range(const ReflectanceCurve& curve, std::size_t samples = 1025);

enum class GamutMapping {
  none,        // keep the values as they are: physically meaningful, possibly above 1 or below 0
  desaturate,  // pull every angle toward its own luminance by one constant factor
};
inline constexpr std::array<GamutMapping, 2> kGamutMappings = {GamutMapping::none,
                                                               GamutMapping::desaturate};
std::string_view gamut_mapping_name(GamutMapping mapping);  // "none", "desaturate"

// The luminance-preserving desaturation F' = Y + s (F - Y), Y the space's luminance of F, with
// the largest s in [0, 1] that brings every channel at every sampled angle into [0, 1]; s = 1
// (the identity) for a curve already in range. F(90 deg) = (1, 1, 1) is kept, and so is each
// angle's luminance: only chroma is given up, the same fraction at every angle.
struct Desaturation {
  Matrix3 matrix{};
  double saturation = 1.0;
};
Desaturation desaturation_into_unit_range(const ReflectanceCurve& curve, ColorSpace space,
                                          std::size_t samples = 1025);

}  // namespace matc
