// The MaterialX shading models matc imports metals from (internal to the importer), one record
// each: the inputs a metal depends on with their specification defaults, the inputs that change
// a look but are not carried, and how the inputs become a matc material (which model, the
// products that make F0 and the edge, their ranges and the words diagnostics use). Adding a
// model is adding a record.
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "materialx_document.h"

namespace matc {

struct MaterialXInputSpec {
  std::string_view name;
  MaterialXType type;
  Rgb default_value;  // a float's default in [0]
};

// An input that changes a metal's look but is not carried, and the value at which it changes
// nothing (weights 0, opacities 1, booleans false): only other values are reported.
struct NotCarriedInput {
  std::string_view name;
  double neutral = 0.0;
};

enum class ImportedModel { artistic, f82_tint };  // the matc material model it becomes

struct MaterialXShadingModel {
  std::string_view node;  // "standard_surface", "open_pbr_surface"
  // F0 = weight x color; the edge = edge_weight x edge_color, or edge_color alone (OpenPBR,
  // whose specular_weight scales the whole Fresnel: a note says so when it is not 1).
  MaterialXInputSpec weight;
  MaterialXInputSpec color;
  MaterialXInputSpec metalness;
  MaterialXInputSpec edge_weight;
  MaterialXInputSpec edge_color;
  MaterialXInputSpec roughness;
  // The coat (docs/coating.md): carried when its weight is above 0.
  MaterialXInputSpec coat_weight;
  MaterialXInputSpec coat_color;
  MaterialXInputSpec coat_roughness;
  MaterialXInputSpec coat_ior;
  // The thin film (docs/material-format.md, "film"): carried when its weight is above 0. A model
  // without a film weight (Standard Surface) has an empty film_weight name: its film is there
  // when its thickness is above 0. The thickness is in nanometres times film_thickness_to_nm.
  MaterialXInputSpec film_weight;
  MaterialXInputSpec film_thickness;
  MaterialXInputSpec film_ior;
  double film_thickness_to_nm;
  std::array<NotCarriedInput, 9> not_carried;
  ImportedModel imported;
  bool edge_scaled_by_weight;
  double max_f0;                // F0 is clamped to [0, max_f0]
  std::string_view f0_words;    // "reflectivity (base x base_color)"
  std::string_view f0_range;    // why that range
  std::string_view edge_words;  // "edge tint (specular x specular_color)"
  bool bakes_image_maps;        // `matc bake` takes its F0 and edge maps
  // Every input its node definition declares (an input not among them is reported).
  std::span<const std::string_view> inputs;
};

std::span<const MaterialXShadingModel> materialx_shading_models();
const MaterialXShadingModel* find_materialx_shading_model(std::string_view node);
// "standard_surface or open_pbr_surface": what diagnostics offer.
std::string materialx_shading_model_names();

}  // namespace matc
