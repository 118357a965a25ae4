// matc eval's options and the pieces of its JSON that bare and coated materials share
// (eval_command.cpp evaluates bare metals and the coefficient-table path, eval_coated.cpp coated
// metals).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "color_options.h"
#include "lut_options.h"
#include "matc/compile/compile.h"
#include "matc/ltc/polygon_light.h"
#include "matc/lut/preintegrate.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/ltc.h"

namespace matc::cli {

struct EvalOptions {
  std::string file;          // a material file or MaterialX document, or:
  std::string material;      // --material: which of a document's materials
  std::string reflectivity;  // --reflectivity and --edge-tint: the coefficient-table path
  std::string edge_tint;
  std::vector<double> mu;
  std::vector<double> ndotv;
  std::vector<double> roughness;
  std::string quad_light;  // "x,y,z;x,y,z;x,y,z;x,y,z" in the shading frame: area-light radiance
  std::size_t light_samples = 0;  // reference samples for --quad-light
  bool no_reference = false;      // --no-reference: no split-sum integral per (NdotV, roughness)
  LutCliOptions lut;
  ColorOptions color;
};

using nlohmann::ordered_json;

// Coefficients by the JSON suffix of what they give: "" for a compiled material, "_table" and
// "_compiled" for the coefficient-table path and the per-material compile beside it.
using LabelledCoefficients = std::vector<std::pair<std::string, runtime::Coefficients>>;

// The (NdotV, roughness) points and the table a Fbar output was read from.
void add_preintegrated_points(const EvalOptions& options, const Lut& lut, ordered_json& out);

// The quad light and the tables its radiance outputs were computed with.
void add_quad_light_description(const EvalOptions& options, const std::vector<Vec3>& quad,
                                const runtime::LtcTableView& ltc, ordered_json& out);

// A coated material (docs/coating.md): both lobes and their sum beside the exact layered curve,
// preintegrated beside the split sums and the Monte-Carlo layered reference, and the quad light.
void add_coated(const EvalOptions& options, const CompiledMaterial& compiled,
                const runtime::BasisView& basis, const std::optional<std::vector<Vec3>>& quad,
                ordered_json& out);

}  // namespace matc::cli
