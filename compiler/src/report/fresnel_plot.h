// The SVG plot of a material's curves: per linear-sRGB channel, F over the angle of incidence
// (exact, ours, Schlick, F82-tint) and below it each approximation's error against the exact curve.
#pragma once

#include <string>
#include <string_view>

#include "report/material_curves.h"

namespace matc {

inline constexpr int kPlotWidth = 960;
inline constexpr int kPlotHeight = 620;

// The colours of the four curves (also the legend's): what the report test looks for on screen.
inline constexpr std::string_view kExactColour = "#000000";
inline constexpr std::string_view kOursColour = "#d95f02";
inline constexpr std::string_view kSchlickColour = "#1b9e77";
inline constexpr std::string_view kF82TintColour = "#7570b3";

// The smallest of 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1 that holds ours' and F82-tint's error
// (Schlick's is often ten times larger and is clipped rather than allowed to flatten the others).
double error_axis_range(const MaterialCurves& curves);

// `title` and `subtitle` are plain text (escaped here).
std::string fresnel_plot_svg(const MaterialCurves& curves, std::string_view title,
                             std::string_view subtitle);

// &, <, >, " and ' as XML entities.
std::string escape_xml(std::string_view text);

}  // namespace matc
