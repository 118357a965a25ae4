// The help texts of options several commands take, written once (lut_options.cpp and
// color_options.cpp register them with typed values, eval_command.cpp with names).
#pragma once

namespace matc::cli {

// The shipped bases, for --basis's help.
#define MATC_BASIS_NAMES_HELP                                                                 \
  "powers (the closed form m^6, mu m^3, mu m^9 with m = 1 - mu, near-minimax coefficients), " \
  "extended (the authors' dielectrics extended with conductors, curves weighted by 1 - F0), " \
  "paper (the authors' construction, coefficients matched at two angles) or f82 (the closed " \
  "form m^5, mu m^6, mu m^11: exact for F82-tint and Schlick curves, for OpenPBR looks); "    \
  "docs/accuracy.md compares them"
// Where one basis is taken (tables, bakes, `matc basis`).
inline constexpr const char* kBasisHelp = "Fresnel basis (default powers): " MATC_BASIS_NAMES_HELP;
// Where a build takes --basis.
inline constexpr const char* kBuildBasisHelp =
    "Fresnel basis: auto (default): each material the basis that holds its curve (f82 for bare "
    "F82-tint metals, powers for the rest, or the material's own \"basis\"), the table a layer "
    "per basis side by side (docs/accuracy.md, \"A basis per material\"); or one for every "
    "material: " MATC_BASIS_NAMES_HELP;
#undef MATC_BASIS_NAMES_HELP
inline constexpr const char* kLutSizeHelp = "LUT width and height in texels";
inline constexpr const char* kLutSamplesHelp = "Hammersley samples per texel";
inline constexpr const char* kLutPrecisionHelp = "Texel precision";
inline constexpr const char* kCoefficientTablePrecisionHelp =
    "Texel precision of the coefficient table DIR/matc_coefficient_table.<ext>";
// Followed by the spaces' names and " (docs/color-spaces.md)".
inline constexpr const char* kColorSpaceHelp =
    "Working space of the outputs, and of RGB values in materials that name none: ";
inline constexpr const char* kGamutMappingHelp =
    "What to do with Fresnel curves that leave [0, 1] in the working space: none (keep them; a "
    "note names each) or desaturate (toward each angle's luminance, by the least constant factor "
    "that fits)";

}  // namespace matc::cli
