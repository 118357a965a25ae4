// Multiple-scattering energy compensation (Kulla & Conty 2017; Turquin 2019) at no per-material
// cost: the directional albedo E(NdotV, roughness) is the LUT's channel 0 (bbar_0), its cosine-
// weighted average E_avg(roughness) is a small table, and a material's average Fresnel is
// F_avg = sum_i c_i m_i with constants m_i of the basis.
#pragma once

#include <array>
#include <vector>

#include "lut/preintegrate.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"

namespace matc {

// m_i = 2 * integral_0^1 b_i(mu) mu dmu, exact for the linearly interpolated basis (m_0 = 1).
std::array<double, runtime::kBasisSize> basis_hemispherical_averages(
    const runtime::BasisView& basis);

// F_avg per channel: the cosine-weighted hemispherical average of the decomposed Fresnel.
runtime::Rgb average_fresnel(const runtime::Coefficients& coefficients,
                             const std::array<double, runtime::kBasisSize>& averages);

// E_avg(roughness_y) = 2 * integral E(mu, roughness_y) mu dmu for each LUT row y, integrated over
// the row's own texels (trapezoid rule in the table's u = sqrt(mu) axis).
std::vector<double> average_albedo(const Lut& lut);

}  // namespace matc
