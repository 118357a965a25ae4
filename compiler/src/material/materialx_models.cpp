#include "materialx_models.h"

#include <string>

namespace matc {
namespace {

// Defaults: Autodesk Standard Surface 1.0.1 as MaterialX's nodedef declares it, and OpenPBR
// Surface 1.1's parameter reference.
constexpr std::array<MaterialXShadingModel, 2> kModels = {{
    {"standard_surface",
     {"base", MaterialXType::float1, {0.8, 0.0, 0.0}},
     {"base_color", MaterialXType::color3, {1.0, 1.0, 1.0}},
     {"metalness", MaterialXType::float1, {0.0, 0.0, 0.0}},
     {"specular", MaterialXType::float1, {1.0, 0.0, 0.0}},
     {"specular_color", MaterialXType::color3, {1.0, 1.0, 1.0}},
     {"specular_roughness", MaterialXType::float1, {0.2, 0.0, 0.0}},
     {"coat", MaterialXType::float1, {0.0, 0.0, 0.0}},
     {"coat_color", MaterialXType::color3, {1.0, 1.0, 1.0}},
     {"coat_roughness", MaterialXType::float1, {0.1, 0.0, 0.0}},
     {"coat_IOR", MaterialXType::float1, {1.5, 0.0, 0.0}},
     {{{"coat_anisotropy"},
       {"sheen"},
       {"thin_film_thickness"},
       {"specular_anisotropy"},
       {"transmission"},
       {"subsurface"},
       {"emission"},
       {"diffuse_roughness"},
       {"coat_affect_color"},
       {"opacity", 1.0}}},
     ImportedModel::artistic,
     /*edge_scaled_by_weight=*/true,
     // MaterialX's artistic_ior clamps the reflectivity to [0, 0.99] (Gulbrandsen's n_max is
     // infinite at 1); chrome-like looks that ask for 1 get 0.99 there, so they get it here too.
     0.99,
     "reflectivity (base x base_color)",
     "as MaterialX's artistic_ior does: [0, 0.99]",
     "edge tint (specular x specular_color)",
     /*bakes_image_maps=*/true},
    {"open_pbr_surface",
     {"base_weight", MaterialXType::float1, {1.0, 0.0, 0.0}},
     {"base_color", MaterialXType::color3, {0.8, 0.8, 0.8}},
     {"base_metalness", MaterialXType::float1, {0.0, 0.0, 0.0}},
     {"specular_weight", MaterialXType::float1, {1.0, 0.0, 0.0}},
     {"specular_color", MaterialXType::color3, {1.0, 1.0, 1.0}},
     {"specular_roughness", MaterialXType::float1, {0.3, 0.0, 0.0}},
     {"coat_weight", MaterialXType::float1, {0.0, 0.0, 0.0}},
     {"coat_color", MaterialXType::color3, {1.0, 1.0, 1.0}},
     {"coat_roughness", MaterialXType::float1, {0.0, 0.0, 0.0}},
     {"coat_ior", MaterialXType::float1, {1.6, 0.0, 0.0}},
     {{{"coat_roughness_anisotropy"},
       {"fuzz_weight"},
       {"thin_film_weight"},
       {"specular_roughness_anisotropy"},
       {"transmission_weight"},
       {"subsurface_weight"},
       {"emission_luminance"},
       {"base_diffuse_roughness"},
       {"geometry_opacity", 1.0},
       {"geometry_thin_walled"}}},
     ImportedModel::f82_tint,
     /*edge_scaled_by_weight=*/false,
     1.0,
     "F0 (base_weight x base_color)",
     "OpenPBR's metal reflectance range [0, 1]",
     "tint (specular_color)",
     /*bakes_image_maps=*/false},
}};

}  // namespace

std::span<const MaterialXShadingModel> materialx_shading_models() {
  return kModels;
}

const MaterialXShadingModel* find_materialx_shading_model(std::string_view node) {
  for (const MaterialXShadingModel& model : kModels)
    if (model.node == node) return &model;
  return nullptr;
}

std::string materialx_shading_model_names() {
  std::string names;
  for (std::size_t i = 0; i < kModels.size(); ++i) {
    if (i > 0) names += i + 1 == kModels.size() ? " or " : ", ";
    names += kModels[i].node;
  }
  return names;
}

}  // namespace matc
