// matc eval --metalness: glTF's metal-rough mix of a metal with glTF's dielectric (docs/gltf.md).
#include "evaluation_parts.h"
#include "lut/comparison_lobes.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/metal_rough.h"
#include "matc/runtime/shader_basis.h"

namespace matc::evaluation {
namespace {

// The dielectric under the coat's transmission at NdotV (1 - the coat lobe's F there, from
// `at_ndotv`) mixed with the base lobe, the coat lobe over both (a bare metal: transmission 1, no
// coat lobe).
runtime::Rgb mix_lobes(const runtime::Rgb& dielectric, const runtime::CoatedFresnel& metal,
                       double metalness, const runtime::CoatedFresnel& at_ndotv) {
  const runtime::Rgb base =
      runtime::metal_rough_under_coat(dielectric, metal.base, metalness, 1.0 - at_ndotv.coat);
  return {base[0] + metal.coat, base[1] + metal.coat, base[2] + metal.coat};
}

}  // namespace

MetalRoughLobes bare_metal_lobes(const runtime::Coefficients& coefficients,
                                 runtime::BasisKind basis, const Lut& lut) {
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(basis);
  return {
      .fresnel = [&coefficients, &shader_basis](double mu) -> runtime::CoatedFresnel {
        return {.base = runtime::evaluate_fresnel(coefficients, shader_basis, mu)};
      },
      .fbar = [&coefficients, &lut](double ndotv, double roughness) -> runtime::CoatedFresnel {
        return {.base = runtime::evaluate_fbar(coefficients, lut.view(), ndotv, roughness)};
      },
  };
}

MetalRoughLobes filmed_metal_lobes(const runtime::FilmTable& table) {
  return {
      .fresnel = [&table](double mu) -> runtime::CoatedFresnel {
        return {.base = runtime::film_fresnel(table, mu)};
      },
      .fbar = [&table](double ndotv, double roughness) -> runtime::CoatedFresnel {
        return {.base = runtime::film_preintegrated(table, ndotv, roughness)};
      },
  };
}

void add_metal_rough(const EvaluationInputs& inputs, const MetalRoughLobes& metal,
                     ordered_json& out) {
  const double metalness = *inputs.metalness;
  const runtime::Rgb f0{runtime::kGltfDielectricF0, runtime::kGltfDielectricF0,
                        runtime::kGltfDielectricF0};
  const runtime::Rgb f90{1.0, 1.0, 1.0};
  out["metalness"] = metalness;
  out["dielectric"] = {{"f0", f0}, {"f90", f90}};
  if (!inputs.mu.empty()) {
    ordered_json dielectric = ordered_json::array(), mixed = ordered_json::array();
    for (const double mu : inputs.mu) {
      const runtime::Rgb d = runtime::dielectric_fresnel(f0, f90, mu);
      dielectric.push_back(d);
      // F at mu: a mirror-like surface, NdotV = mu.
      const runtime::CoatedFresnel lobes = metal.fresnel(mu);
      mixed.push_back(mix_lobes(d, lobes, metalness, lobes));
    }
    out["F_dielectric"] = std::move(dielectric);
    out["F_metal_rough"] = std::move(mixed);
  }
  if (!inputs.ndotv.empty()) {
    // Schlick's split sum is f0 x + (f90 - f0) y from a table of its lobes (albedo x, the
    // (1 - mu)^5 lobe y), baked as matc's own table is.
    const ComparisonLobes lobes(runtime::shipped_basis(inputs.basis).samples());
    const Lut schlick_lut = preintegrate_lut(lobes.view(), inputs.bake);
    ordered_json dielectric = ordered_json::array(), mixed = ordered_json::array();
    for (std::size_t i = 0; i < inputs.ndotv.size(); ++i) {
      const auto lobe =
          runtime::sample_lut(schlick_lut.view(), inputs.ndotv[i], inputs.roughness[i]);
      runtime::Rgb d{};
      for (std::size_t c = 0; c < 3; ++c)
        d[c] = f0[c] * lobe[0] + (f90[c] - f0[c]) * lobe[1];
      dielectric.push_back(d);
      mixed.push_back(mix_lobes(d, metal.fbar(inputs.ndotv[i], inputs.roughness[i]), metalness,
                                metal.fresnel(inputs.ndotv[i])));
    }
    out["Fbar_dielectric"] = std::move(dielectric);
    out["Fbar_metal_rough"] = std::move(mixed);
  }
}

}  // namespace matc::evaluation
