// A material evaluated at given cosines and (NdotV, roughness) pairs, beside its references, as
// JSON: what `matc eval` prints (docs/cli.md): F as the shaders compute it and the exact curve;
// Fbar from the table as a renderer samples it and from the table's closed form, beside the exact
// split-sum integral; a coated material's lobes and layered references; a quad light's radiance by
// LTC beside the exact integral; the coefficient-table path for Gulbrandsen's r, g. Native builds.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "matc/api/compiled_material.h"
#include "matc/api/tables.h"

namespace matc::api {

inline constexpr std::size_t kDefaultLightSamples = std::size_t{1} << 20;

struct EvaluationOptions {
  std::vector<double> mu;         // F at these cosines, each in [0, 1]
  std::vector<double> ndotv;      // Fbar at these NdotV values, each in [0, 1] ...
  std::vector<double> roughness;  // ... and one perceptual roughness per NdotV
  // Fbar_reference, the exact split-sum integral per pair (a Monte-Carlo integral each: the slow
  // part of evaluating many pairs), a coated material's layered references, and a quad light's
  // exact integral (L_reference) and L_ltc_exact_fresnel; false: the shaders' values alone.
  bool reference = true;
  // A quad light of radiance 1: its four vertices in the shading frame (normal +z, view in the
  // xz-plane towards +x); empty: none. Needs pairs.
  std::vector<std::array<double, 3>> quad_light;
  std::size_t light_samples = kDefaultLightSamples;  // of the quad light's reference, 16..2^26
  CompileOptions compile;                            // the basis and the colour options
  std::size_t lut_size = kDefaultLutSize;            // the table Fbar is read from
  std::size_t lut_samples = kDefaultLutSamples;
  std::string lut_precision;                // f32 (default) or f16
  std::string coefficient_table_precision;  // f16 (default) or f32: the coefficient-table path
  // glTF's metal-rough model (docs/gltf.md): F and Fbar of the metal mixed by this metalness, in
  // [0, 1], with glTF's default dielectric (F0 0.04, F90 1): F_metal_rough, Fbar_metal_rough and
  // the dielectric's F_dielectric, Fbar_dielectric. Bare metals only.
  std::optional<double> metalness;
  // A thickness per pixel (docs/thin-film.md): the film at this thickness in nanometres, within
  // the range of a material whose film has one, read from its stack as the shaders read it at
  // that thickness coordinate; absent: the range's maximum, as without a thickness texture.
  std::optional<double> film_thickness;
};

// The evaluation of `material` as JSON text. Throws std::invalid_argument naming an option out of
// range or outside its names, or contradicting another (no cosines and no pairs, pairs of two
// lengths, a quad light without pairs).
std::string evaluate(const Material& material, const EvaluationOptions& options);
// The coefficient-table path for Gulbrandsen's reflectivity and edge tint per channel (each in
// [0, 1]): F and Fbar from the table's coefficients beside the per-material compile.
std::string evaluate_artistic(const Rgb& reflectivity, const Rgb& edge_tint,
                              const EvaluationOptions& options);

// "x,y,z;x,y,z;x,y,z;x,y,z" (spaces allowed): a quad light's vertices, checked as evaluate checks
// them. Throws std::invalid_argument saying what is wrong (a non-finite coordinate, coincident
// vertices, no area, vertices off one plane, a non-convex outline, the shading point in its
// plane, every vertex below the horizon).
std::vector<std::array<double, 3>> parse_quad_light(std::string_view text);

}  // namespace matc::api
