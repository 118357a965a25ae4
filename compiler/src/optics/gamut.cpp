#include "optics/gamut.h"

#include <algorithm>
#include <array>

namespace matc {
namespace {

double cosine(std::size_t j, std::size_t samples) {
  return static_cast<double>(j) / static_cast<double>(samples - 1);
}

}  // namespace

bool CurveRange::within_unit_range() const {
  return *std::min_element(min.begin(), min.end()) >= -kGamutTolerance &&
         *std::max_element(max.begin(), max.end()) <= 1.0 + kGamutTolerance;
}

CurveRange measure_curve_range(const ReflectanceCurve& curve, std::size_t samples) {
  CurveRange range;
  range.min = curve.at(0.0);
  range.max = range.min;
  for (std::size_t j = 1; j < samples; ++j) {
    const Rgb value = curve.at(cosine(j, samples));
    for (std::size_t c = 0; c < 3; ++c) {
      range.min[c] = std::min(range.min[c], value[c]);
      range.max[c] = std::max(range.max[c], value[c]);
    }
  }
  return range;
}

std::string_view gamut_mapping_name(GamutMapping mapping) {
  return mapping == GamutMapping::none ? "none" : "desaturate";
}

Desaturation desaturation_into_unit_range(const ReflectanceCurve& curve, ColorSpace space,
                                          std::size_t samples) {
  const Matrix3 to_xyz = rgb_to_xyz(space);
  const Rgb luminance = to_xyz[1];  // the Y row: sums to 1, so grey stays grey
  double s = 1.0;
  for (std::size_t j = 0; j < samples; ++j) {
    const Rgb f = curve.at(cosine(j, samples));
    const double y = luminance[0] * f[0] + luminance[1] * f[1] + luminance[2] * f[2];
    for (std::size_t c = 0; c < 3; ++c) {
      // Y + s (F_c - Y) must stay in [0, 1]; a luminance outside it cannot be mapped (s = 0).
      if (f[c] > 1.0 + kGamutTolerance) s = std::min(s, y >= 1.0 ? 0.0 : (1.0 - y) / (f[c] - y));
      if (f[c] < -kGamutTolerance) s = std::min(s, y <= 0.0 ? 0.0 : y / (y - f[c]));
    }
  }
  Desaturation result;
  result.saturation = s;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      result.matrix[i][j] = (i == j ? s : 0.0) + (1.0 - s) * luminance[j];
  return result;
}

}  // namespace matc
