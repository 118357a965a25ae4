#include "materialx_models.h"

#include <string>

namespace matc {
namespace {

// The inputs of MaterialX's node definitions: ND_standard_surface_surfaceshader_100 (1.0.1 changes
// two defaults only) and ND_open_pbr_surface_surfaceshader (OpenPBR 1.1), in
// libraries/bxdf/standard_surface.mtlx and open_pbr_surface.mtlx.
constexpr std::array<std::string_view, 42> kStandardSurfaceInputs = {
    "base",
    "base_color",
    "diffuse_roughness",
    "metalness",
    "specular",
    "specular_color",
    "specular_roughness",
    "specular_IOR",
    "specular_anisotropy",
    "specular_rotation",
    "transmission",
    "transmission_color",
    "transmission_depth",
    "transmission_scatter",
    "transmission_scatter_anisotropy",
    "transmission_dispersion",
    "transmission_extra_roughness",
    "subsurface",
    "subsurface_color",
    "subsurface_radius",
    "subsurface_scale",
    "subsurface_anisotropy",
    "sheen",
    "sheen_color",
    "sheen_roughness",
    "coat",
    "coat_color",
    "coat_roughness",
    "coat_anisotropy",
    "coat_rotation",
    "coat_IOR",
    "coat_normal",
    "coat_affect_color",
    "coat_affect_roughness",
    "thin_film_thickness",
    "thin_film_IOR",
    "emission",
    "emission_color",
    "opacity",
    "thin_walled",
    "normal",
    "tangent",
};
constexpr std::array<std::string_view, 41> kOpenPbrInputs = {
    "base_weight",
    "base_color",
    "base_diffuse_roughness",
    "base_metalness",
    "specular_weight",
    "specular_color",
    "specular_roughness",
    "specular_ior",
    "specular_roughness_anisotropy",
    "transmission_weight",
    "transmission_color",
    "transmission_depth",
    "transmission_scatter",
    "transmission_scatter_anisotropy",
    "transmission_dispersion_scale",
    "transmission_dispersion_abbe_number",
    "subsurface_weight",
    "subsurface_color",
    "subsurface_radius",
    "subsurface_radius_scale",
    "subsurface_scatter_anisotropy",
    "fuzz_weight",
    "fuzz_color",
    "fuzz_roughness",
    "coat_weight",
    "coat_color",
    "coat_roughness",
    "coat_roughness_anisotropy",
    "coat_ior",
    "coat_darkening",
    "thin_film_weight",
    "thin_film_thickness",
    "thin_film_ior",
    "emission_luminance",
    "emission_color",
    "geometry_opacity",
    "geometry_thin_walled",
    "geometry_normal",
    "geometry_coat_normal",
    "geometry_tangent",
    "geometry_coat_tangent",
};

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
     {"", MaterialXType::float1, {1.0, 0.0, 0.0}},
     {"thin_film_thickness", MaterialXType::float1, {0.0, 0.0, 0.0}},
     {"thin_film_IOR", MaterialXType::float1, {1.5, 0.0, 0.0}},
     1.0,  // Standard Surface's thin_film_thickness is in nanometres
     {{{"coat_anisotropy"},
       {"sheen"},
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
     /*bakes_image_maps=*/true,
     kStandardSurfaceInputs},
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
     {"thin_film_weight", MaterialXType::float1, {0.0, 0.0, 0.0}},
     {"thin_film_thickness", MaterialXType::float1, {0.5, 0.0, 0.0}},
     {"thin_film_ior", MaterialXType::float1, {1.4, 0.0, 0.0}},
     1000.0,  // OpenPBR's thin_film_thickness is in micrometres
     {{{"coat_roughness_anisotropy"},
       {"fuzz_weight"},
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
     /*bakes_image_maps=*/false,
     kOpenPbrInputs},
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
