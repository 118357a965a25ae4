// matc::api::evaluate's options resolved to the library's values, and the pieces of its JSON that
// bare and coated materials share (evaluation.cpp evaluates bare metals and the coefficient-table
// path, coated_evaluation.cpp coated metals).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "compile/compile.h"
#include "formats/table_format.h"
#include "lut/preintegrate.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/vec3.h"

namespace matc::evaluation {

using runtime::Vec3;

struct EvaluationInputs {
  std::vector<double> mu;
  std::vector<double> ndotv;
  std::vector<double> roughness;
  bool reference = true;
  std::optional<std::vector<Vec3>> quad;
  std::size_t light_samples = 0;
  LutOptions bake;
  LutPrecision precision = LutPrecision::f32;
  runtime::BasisKind basis = runtime::kDefaultBasis;
  LutPrecision coefficient_table_precision = LutPrecision::f16;
  ColorOptions color;
  std::optional<double> metalness;  // glTF's metal-rough mix with glTF's dielectric, when given
  std::optional<double> film_thickness_nm;  // a thickness per pixel's film at this thickness
};

using nlohmann::ordered_json;

// Coefficients by the JSON suffix of what they give: "" for a compiled material, "_table" and
// "_compiled" for the coefficient-table path and the per-material compile beside it.
using LabelledCoefficients = std::vector<std::pair<std::string, runtime::Coefficients>>;

// The (NdotV, roughness) points and the table a Fbar output was read from.
void add_preintegrated_points(const EvaluationInputs& inputs, const Lut& lut, ordered_json& out);

// The quad light and the tables its radiance outputs were computed with.
void add_quad_light_description(const EvaluationInputs& inputs, const std::vector<Vec3>& quad,
                                const runtime::LtcTableView& ltc, ordered_json& out);

// The metal's side of glTF's metal-rough mix: its lobes' F at mu and preintegrated F at (NdotV,
// roughness) (a bare metal's in .base; a coated one's base and coat lobes). The coat's
// transmission at NdotV is 1 - fresnel(NdotV).coat (runtime::coat_transmission; 1 for a bare
// metal).
struct MetalRoughLobes {
  std::function<runtime::CoatedFresnel(double mu)> fresnel;
  std::function<runtime::CoatedFresnel(double ndotv, double roughness)> fbar;
};

// A bare metal's lobes: `coefficients` with `basis`, preintegrated through `lut` (all three kept
// alive by the caller).
MetalRoughLobes bare_metal_lobes(const runtime::Coefficients& coefficients,
                                 runtime::BasisKind basis, const Lut& lut);

// A filmed metal's lobe: its tables (runtime/film_table.h; kept alive by the caller).
MetalRoughLobes filmed_metal_lobes(const runtime::FilmTable& table);

// glTF's metal-rough model at `inputs.metalness` (docs/gltf.md): F and Fbar of the metal mixed
// with glTF's default dielectric (F0 0.04, F90 1; Schlick's curve, its split sum from a table
// baked like matc's), as matc_metal_rough and matc_dielectric_fresnel compute them (under a coat,
// matc_metal_rough_<name>: the dielectric times the coat's transmission, the coat lobe over the
// mix, F at mu with NdotV = mu): F_metal_rough, Fbar_metal_rough, and the dielectric's own
// F_dielectric, Fbar_dielectric.
void add_metal_rough(const EvaluationInputs& inputs, const MetalRoughLobes& metal,
                     ordered_json& out);

// A coated material (docs/coating.md): both lobes and their sum beside the exact layered curve,
// preintegrated beside the split sums and the Monte-Carlo layered reference, and the quad light.
void add_coated(const EvaluationInputs& inputs, const CompiledMaterial& compiled,
                const runtime::BasisView& basis, ordered_json& out);

}  // namespace matc::evaluation
