// Fits the closed form of the preintegrated table (matc/runtime/analytic_lut.h) to a baked table,
// and writes it as the checked-in source `matc basis analytic-lut` produces.
#pragma once

#include <string>
#include <vector>

#include "lut/preintegrate.h"
#include "matc/runtime/analytic_lut.h"

namespace matc {

// Fits `table` (baked for the shipped basis `kind`) at its texel centres: E by linear least
// squares, then the quadrature (mu_a, mu_b, t) by Levenberg-Marquardt on bbar_1..bbar_3 (first
// with t free, then with t clamped to [0, 1] as the shaders evaluate it), each weighted by the
// root mean square of its coefficient over the measured metals (c_3 is ~7x the others). Chebyshev
// polynomials keep the coefficients small, so float32 shaders evaluate them accurately.
// Deterministic: a fixed start and iteration limit, no threads.
runtime::AnalyticLutCoefficients fit_analytic_lut(const Lut& table, runtime::BasisKind kind);

// The same for a shipped basis' default table (128 x 128, 1024 samples per texel).
runtime::AnalyticLutCoefficients fit_shipped_analytic_lut(runtime::BasisKind kind);

// The materials every texture-free Fbar is measured on (here and by the benchmarks): the measured
// metals (presets without a caveat), their coefficients solved in `basis`.
std::vector<runtime::Coefficients> measured_metal_coefficients(const runtime::BasisView& basis);

// max and mean |Fbar_analytic - Fbar_texture| over the measured metals (presets without a caveat,
// coefficients solved in `basis`) and a 65 x 65 grid of (NdotV, roughness) in [0, 1]^2, per RGB
// channel: issue #20's measure, targets 0.005 and 5e-4.
struct AnalyticLutError {
  double max = 0.0;
  double mean = 0.0;
  double max_away_from_grazing = 0.0;  // NdotV >= 0.25
};
AnalyticLutError analytic_lut_error(const runtime::AnalyticLutCoefficients& analytic,
                                    const Lut& texture, const runtime::BasisView& basis);

// src/generated/<basis>_analytic_lut_table.cpp, defining runtime::<basis>_analytic_lut().
std::string analytic_lut_source(runtime::BasisKind kind,
                                const runtime::AnalyticLutCoefficients& coefficients);

}  // namespace matc
