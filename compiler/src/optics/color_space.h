// Linear RGB working spaces and the conversions between them: matrices derived from each space's
// primaries and white point (SMPTE RP 177), and Bradford chromatic adaptation between whites.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "matc/runtime/fresnel.h"

namespace matc {

using runtime::Rgb;
using Matrix3 = std::array<std::array<double, 3>, 3>;
using Xyz = std::array<double, 3>;

enum class ColorSpace { lin_rec709, acescg, lin_rec2020, lin_displayp3 };
inline constexpr ColorSpace kDefaultColorSpace = ColorSpace::lin_rec709;

struct Chromaticity {
  double x = 0.0;
  double y = 0.0;
};

struct ColorSpaceDefinition {
  ColorSpace id;
  std::string_view name;  // MaterialX's name for it, what --color-space and files accept
  std::string_view description;
  Chromaticity red, green, blue, white;
};

// Every supported space, lin_rec709 first.
std::span<const ColorSpaceDefinition> color_spaces();
const ColorSpaceDefinition& color_space_definition(ColorSpace space);
std::string_view color_space_name(ColorSpace space);
// The space a name (or an accepted alias such as "lin_srgb", "lin_ap1") stands for.
std::optional<ColorSpace> find_color_space(std::string_view name);
// MaterialX's encoded (gamma or sRGB curve) spaces: srgb_texture, g22_rec709, g18_rec709, g22_ap1,
// g18_ap1, srgb_displayp3, which the MaterialX importer decodes.
bool is_encoded_color_space(std::string_view name);
// Decodes one encoded value of such a space to linear, and names the linear space it lands in.
struct DecodedColor {
  double value;
  ColorSpace space;
};
std::optional<DecodedColor> decode_color_value(std::string_view encoded_space, double value);

// "lin_rec709, acescg, lin_rec2020, lin_displayp3" for diagnostics.
std::string color_space_names();

Matrix3 multiply(const Matrix3& a, const Matrix3& b);
Rgb multiply(const Matrix3& m, const Rgb& v);
Matrix3 inverse(const Matrix3& m);

// The XYZ of a chromaticity at Y = 1.
Xyz xyz_from_chromaticity(Chromaticity c);
// Linear RGB -> CIE XYZ for the space (RGB (1, 1, 1) maps to its white at Y = 1).
Matrix3 rgb_to_xyz(ColorSpace space);
// Bradford's von Kries transform taking `from_white` to `to_white` (both XYZ).
Matrix3 bradford_adaptation(const Xyz& from_white, const Xyz& to_white);
// Linear RGB in `from` -> linear RGB in `to`, adapting white to white with Bradford.
Matrix3 rgb_to_rgb(ColorSpace from, ColorSpace to);

}  // namespace matc
