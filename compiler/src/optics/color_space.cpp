#include "optics/color_space.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace matc {
namespace {

// Primaries and whites from each space's standard: ITU-R BT.709, SMPTE ST 2065-1 / ACES TB-2014-004
// (AP1 and the ACES white), ITU-R BT.2020, SMPTE EG 432-1 (Display P3, D65).
constexpr Chromaticity kD65{0.3127, 0.3290};
constexpr Chromaticity kAcesWhite{0.32168, 0.33767};

constexpr std::array<ColorSpaceDefinition, 4> kSpaces = {{
    {ColorSpace::lin_rec709,
     "lin_rec709",
     "linear Rec.709 / sRGB primaries, D65 white",
     {0.640, 0.330},
     {0.300, 0.600},
     {0.150, 0.060},
     kD65},
    {ColorSpace::acescg,
     "acescg",
     "ACEScg: ACES AP1 primaries, ACES white (about D60)",
     {0.713, 0.293},
     {0.165, 0.830},
     {0.128, 0.044},
     kAcesWhite},
    {ColorSpace::lin_rec2020,
     "lin_rec2020",
     "linear Rec.2020 primaries, D65 white",
     {0.708, 0.292},
     {0.170, 0.797},
     {0.131, 0.046},
     kD65},
    {ColorSpace::lin_displayp3,
     "lin_displayp3",
     "linear Display P3 (DCI-P3 primaries, D65 white)",
     {0.680, 0.320},
     {0.265, 0.690},
     {0.150, 0.060},
     kD65},
}};

struct Alias {
  std::string_view name;
  ColorSpace space;
};
// Other names the same spaces go by (MaterialX and OCIO config spellings).
constexpr std::array<Alias, 6> kAliases = {{
    {"lin_srgb", ColorSpace::lin_rec709},
    {"srgb_linear", ColorSpace::lin_rec709},
    {"lin_ap1", ColorSpace::acescg},
    {"ACEScg", ColorSpace::acescg},
    {"rec2020_linear", ColorSpace::lin_rec2020},
    {"lin_p3d65", ColorSpace::lin_displayp3},
}};

// Bradford's cone-response matrix (Lam 1985; the constants of ICC.1 Annex E).
constexpr Matrix3 kBradford = {{
    {0.8951, 0.2664, -0.1614},
    {-0.7502, 1.7135, 0.0367},
    {0.0389, -0.0685, 1.0296},
}};

enum class Transfer { srgb, gamma22, gamma18 };
struct EncodedSpace {
  std::string_view name;
  Transfer transfer;
  ColorSpace linear;
};
constexpr std::array<EncodedSpace, 6> kEncodedSpaces = {{
    {"srgb_texture", Transfer::srgb, ColorSpace::lin_rec709},
    {"g22_rec709", Transfer::gamma22, ColorSpace::lin_rec709},
    {"g18_rec709", Transfer::gamma18, ColorSpace::lin_rec709},
    {"g22_ap1", Transfer::gamma22, ColorSpace::acescg},
    {"g18_ap1", Transfer::gamma18, ColorSpace::acescg},
    {"srgb_displayp3", Transfer::srgb, ColorSpace::lin_displayp3},
}};

}  // namespace

bool is_encoded_color_space(std::string_view name) {
  return std::any_of(kEncodedSpaces.begin(), kEncodedSpaces.end(),
                     [&](const EncodedSpace& space) { return space.name == name; });
}

std::optional<DecodedColor> decode_color_value(std::string_view encoded_space, double value) {
  for (const EncodedSpace& space : kEncodedSpaces) {
    if (space.name != encoded_space) continue;
    switch (space.transfer) {
      case Transfer::srgb:  // IEC 61966-2-1's piecewise curve
        return DecodedColor{
            value <= 0.04045 ? value / 12.92 : std::pow((value + 0.055) / 1.055, 2.4),
            space.linear};
      case Transfer::gamma22:
        return DecodedColor{std::pow(std::max(value, 0.0), 2.2), space.linear};
      case Transfer::gamma18:
        return DecodedColor{std::pow(std::max(value, 0.0), 1.8), space.linear};
    }
  }
  return std::nullopt;
}

std::span<const ColorSpaceDefinition> color_spaces() {
  return kSpaces;
}

const ColorSpaceDefinition& color_space_definition(ColorSpace space) {
  for (const auto& definition : kSpaces)
    if (definition.id == space) return definition;
  throw std::logic_error("unknown colour space");
}

std::string_view color_space_name(ColorSpace space) {
  return color_space_definition(space).name;
}

std::optional<ColorSpace> find_color_space(std::string_view name) {
  for (const auto& definition : kSpaces)
    if (definition.name == name) return definition.id;
  for (const Alias& alias : kAliases)
    if (alias.name == name) return alias.space;
  return std::nullopt;
}

std::string color_space_names() {
  std::string names;
  for (const auto& definition : kSpaces) {
    if (!names.empty()) names += ", ";
    names += definition.name;
  }
  return names;
}

Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
  Matrix3 result{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 3; ++k)
        result[i][j] += a[i][k] * b[k][j];
  return result;
}

Rgb multiply(const Matrix3& m, const Rgb& v) {
  Rgb result{};
  for (std::size_t i = 0; i < 3; ++i)
    result[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  return result;
}

Matrix3 inverse(const Matrix3& m) {
  // The adjugate over the determinant: exact enough for these well-conditioned 3x3 matrices.
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double determinant = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  if (determinant == 0.0) throw std::logic_error("singular colour matrix");
  const double s = 1.0 / determinant;
  return {{
      {c00 * s, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * s,
       (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * s},
      {c01 * s, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * s,
       (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * s},
      {c02 * s, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * s,
       (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * s},
  }};
}

Xyz xyz_from_chromaticity(Chromaticity c) {
  return {c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y};
}

Matrix3 rgb_to_xyz(ColorSpace space) {
  // Columns are the primaries' XYZ, each scaled so that they sum to the white (SMPTE RP 177).
  const ColorSpaceDefinition& d = color_space_definition(space);
  const Xyz r = xyz_from_chromaticity(d.red);
  const Xyz g = xyz_from_chromaticity(d.green);
  const Xyz b = xyz_from_chromaticity(d.blue);
  const Matrix3 primaries = {{{r[0], g[0], b[0]}, {r[1], g[1], b[1]}, {r[2], g[2], b[2]}}};
  const Rgb scale = multiply(inverse(primaries), xyz_from_chromaticity(d.white));
  Matrix3 result = primaries;
  for (auto& row : result)
    for (std::size_t j = 0; j < 3; ++j)
      row[j] *= scale[j];
  return result;
}

Matrix3 bradford_adaptation(const Xyz& from_white, const Xyz& to_white) {
  const Rgb from_cone = multiply(kBradford, from_white);
  const Rgb to_cone = multiply(kBradford, to_white);
  Matrix3 gain{};
  for (std::size_t i = 0; i < 3; ++i)
    gain[i][i] = to_cone[i] / from_cone[i];
  return multiply(inverse(kBradford), multiply(gain, kBradford));
}

Matrix3 rgb_to_rgb(ColorSpace from, ColorSpace to) {
  const Matrix3 adapt =
      bradford_adaptation(xyz_from_chromaticity(color_space_definition(from).white),
                          xyz_from_chromaticity(color_space_definition(to).white));
  return multiply(inverse(rgb_to_xyz(to)), multiply(adapt, rgb_to_xyz(from)));
}

}  // namespace matc
