#include "report/material_curves.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "matc/runtime/coat.h"
#include "optics/coat.h"
#include "optics/fresnel.h"

namespace matc {

MaterialCurves sample_material_curves(const CompiledMaterial& compiled,
                                      const runtime::ShaderBasis& shader_basis) {
  const auto in_air = make_reflectance_curve(compiled.material, compiled.color);
  // A coated material (docs/coating.md) is plotted whole: the exact layered curve, both lobes as
  // the shaders sum them, Schlick's and F82-tint's from the layered F0 and F(1/7).
  std::unique_ptr<ReflectanceCurve> under_coat;
  std::optional<LayeredCurve> layered;
  if (const auto& coat = compiled.coat) {
    under_coat = make_under_coat_curve(compiled.material, compiled.color.working_space);
    layered.emplace(*in_air, *under_coat, coat->input.weight, coat->input.ior, coat->input.color);
  }
  const ReflectanceCurve& exact =
      layered ? static_cast<const ReflectanceCurve&>(*layered) : *in_air;
  const Rgb& f0 = compiled.coat ? compiled.coat->layered_f0 : compiled.f0;
  const Rgb& f82_value = compiled.coat ? compiled.coat->layered_f82 : compiled.f82;
  // What the shaders compute: a filmed metal's F from its table (under a coat, the base lobe's).
  const auto ours = [&](double mu) { return shader_fresnel(compiled, shader_basis, mu); };
  MaterialCurves curves;
  for (std::size_t i = 0; i < kReportAngles; ++i) {
    const double theta = 90.0 * static_cast<double>(i) / static_cast<double>(kReportAngles - 1);
    // cos(90 deg) in floating point is 6e-17, not 0: pin the end so grazing is exactly mu = 0.
    const double mu = i + 1 == kReportAngles ? 0.0 : std::cos(theta * std::numbers::pi / 180.0);
    Rgb schlick{};
    Rgb f82{};
    for (std::size_t c = 0; c < 3; ++c) {
      schlick[c] = fresnel_schlick(mu, f0[c]);
      f82[c] = fresnel_f82_tint(mu, f0[c], f82_value[c]);
    }
    curves.theta_degrees.push_back(theta);
    curves.exact.push_back(exact.at(mu));
    curves.ours.push_back(ours(mu));
    curves.schlick.push_back(schlick);
    curves.f82_tint.push_back(f82);
  }
  return curves;
}

std::string material_curves_csv(const MaterialCurves& curves) {
  std::string out = "theta_deg";
  for (const char* model : {"exact", "ours", "schlick", "f82_tint"})
    for (const char* channel : {"r", "g", "b"})
      out.append(fmt::format(",{}_{}", model, channel));
  out += '\n';
  for (std::size_t i = 0; i < curves.theta_degrees.size(); ++i) {
    out.append(fmt::format("{:.1f}", curves.theta_degrees[i]));
    for (const auto* model : {&curves.exact, &curves.ours, &curves.schlick, &curves.f82_tint})
      for (const double value : (*model)[i])
        out.append(fmt::format(",{:.6f}", value));
    out += '\n';
  }
  return out;
}

}  // namespace matc
