// Compiling one validated material: its exact curve, coefficients and measured accuracy.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "matc/diagnostics.h"
#include "matc/fit/accuracy.h"
#include "matc/material/material.h"
#include "matc/optics/gulbrandsen.h"
#include "matc/optics/reflectance_curve.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"

namespace matc {

struct CompiledMaterial {
  Material material;
  runtime::Coefficients coefficients{};
  FitAccuracy accuracy;
  Rgb f0{};   // exact reflectance at normal incidence
  Rgb f82{};  // exact reflectance at mu = 1/7 (about 82 degrees)
  // Cosine-weighted average of the decomposed Fresnel, for multiple-scattering compensation.
  Rgb average_fresnel{};
  // The complex IOR per channel and its Gulbrandsen equivalent; absent for spectral materials,
  // whose RGB curve is an integral over many IORs.
  std::optional<std::array<ComplexIor, 3>> ior;
  std::optional<std::array<ArtisticParameters, 3>> artistic;
};

// The exact RGB Fresnel curve a material describes.
std::unique_ptr<ReflectanceCurve> make_reflectance_curve(const Material& material);

CompiledMaterial compile_material(const Material& material, const runtime::BasisView& basis);

// Above this max |F - exact| (2.5x the worst of the 23 measured metals with the paper basis,
// 8x with the default; docs/accuracy.md) a fit is called poor.
inline constexpr double kPoorFitMaxError = 0.05;

// A warning, at the material's name, when the decomposition misses the exact curve by more than
// kPoorFitMaxError: the measured error, Schlick's and F82-tint's beside it, and what to try.
void warn_if_poor_fit(const CompiledMaterial& compiled, Diagnostics& diagnostics);

// The per-material output `<name>.json` (field reference: docs/material-format.md).
nlohmann::ordered_json compiled_material_json(const CompiledMaterial& compiled,
                                              const runtime::BasisView& basis);

}  // namespace matc
