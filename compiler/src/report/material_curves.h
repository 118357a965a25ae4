// A compiled material's Fresnel curves sampled over the angle of incidence: exact, ours (as the
// shaders evaluate it), Schlick and F82-tint. What `matc report` plots and tabulates. A coated
// material's are the whole surface's: the exact layered curve, both lobes summed, Schlick's and
// F82-tint's from the layered F0 and F(1/7).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "compile/compile.h"
#include "matc/runtime/shader_basis.h"

namespace matc {

// Every half degree from 0 (normal incidence) to 90 (grazing).
inline constexpr std::size_t kReportAngles = 181;

struct MaterialCurves {
  std::vector<double> theta_degrees;
  std::vector<Rgb> exact;
  std::vector<Rgb> ours;
  std::vector<Rgb> schlick;   // exact F0
  std::vector<Rgb> f82_tint;  // exact F0 and F(1/7)
};

MaterialCurves sample_material_curves(const CompiledMaterial& compiled,
                                      const runtime::ShaderBasis& shader_basis);

// theta_deg, then exact, ours, Schlick and F82-tint per channel: one row per angle.
std::string material_curves_csv(const MaterialCurves& curves);

}  // namespace matc
