// Compiling one validated material: its exact curve, coefficients and measured accuracy.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "base/diagnostics.h"
#include "fit/accuracy.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/film_table.h"
#include "matc/runtime/fresnel.h"
#include "material/material.h"
#include "optics/gamut.h"
#include "optics/gulbrandsen.h"
#include "optics/reflectance_curve.h"

namespace matc {

// The working space a build's outputs are in (--color-space) and what happens to curves that leave
// [0, 1] in it (--gamut-mapping); docs/color-spaces.md.
struct ColorOptions {
  ColorSpace working_space = kDefaultColorSpace;
  GamutMapping gamut_mapping = GamutMapping::none;
};

// What a `coat` block compiles to (docs/coating.md): the metal as seen through the coat and the
// coat's own Fresnel, each fitted with the same basis, and how far the layering the shaders do
// from them is from the exact layered reflectance.
struct CompiledCoat {
  CoatInput input;
  runtime::CoatCoefficients coefficients{};
  ErrorStats under_coat_error;  // the under-coat fit against its exact curve (UnderCoatCurve)
  double coat_max_error = 0.0;  // the coat's dielectric fit, max |F - exact|
  // The shaders' F_coat + F_base (runtime::evaluate_coated_fresnel) against LayeredCurve.
  ErrorStats layered_error;
  Rgb layered_f0{};   // the exact layered reflectance at normal incidence
  Rgb layered_f82{};  // ... and at mu = 1/7
  // The whole surface against the exact layered curve: ours (layered_error), Schlick's and
  // F82-tint's from the layered F0 and F(1/7). What `matc report` shows for a coated material.
  FitAccuracy layered_accuracy;
};

struct CompiledMaterial {
  Material material;
  // The shipped basis the coefficients (and the coat's) are in: what every output of this
  // material reads (its functions, its layer of the table, <name>.json).
  runtime::BasisKind basis = runtime::kDefaultBasis;
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
  ColorOptions color;
  // The exact curve's extent in the working space before any gamut mapping, and the saturation
  // the mapping kept (1: nothing changed).
  CurveRange range;
  double saturation = 1.0;
  // Whether the decomposed curve provably stays above 0 (fit/nonnegative_curve.h): then the
  // material's own shader functions leave out the clamp at 0.
  bool fresnel_nonnegative = false;
  std::optional<CompiledCoat> coat;  // from the material's `coat` block
  // A filmed metal's own tables (runtime/film_table.h): what its shader functions read for F and
  // Fbar, the 4-term fit not holding a film's interference. Its coefficients still give F0 (energy
  // compensation) and the glTF extension's. Absent without a visible film.
  std::optional<runtime::FilmTable> film_table;
  ErrorStats film_table_error;  // the table's F against the exact curve, on the accuracy grid
  // A thickness per pixel (the film's thickness a range): the tables over the range, what its
  // shaders sample (<name>.film.<ext>); film_table is then its last slice, the film at the
  // range's maximum, for whatever reads the material without a thickness texture.
  std::optional<runtime::FilmStack> film_stack;
  double film_stack_error = 0.0;  // BakedFilmStack::thickness_error
};

// Whether a material's film shows: a film of 0 nm, of no coverage or of index 1 is the bare metal.
bool has_visible_film(const Material& material);

// What the shader functions of a compiled material compute, against its exact curve: the film
// table's, or else the decomposition's.
const ErrorStats& shader_fresnel_error(const CompiledMaterial& compiled);

// A coated material's two lobes at mu = dot(V, H) as its shaders compute them: the base from the
// metal's coefficients, or from its film's table where a film lies under the coat.
runtime::CoatedFresnel shader_coated_fresnel(const CompiledMaterial& compiled,
                                             const runtime::ShaderBasis& basis, double mu);
// F at mu as the material's shaders compute it: its coefficients, a filmed metal's table, or a
// coated material's two lobes summed.
Rgb shader_fresnel(const CompiledMaterial& compiled, const runtime::ShaderBasis& basis, double mu);

// The space a material's RGB values are in: its own color_space, or else the working space.
ColorSpace input_color_space(const Material& material, ColorSpace working_space);

// The exact RGB Fresnel curve a material describes in the working space, before gamut mapping.
std::unique_ptr<ReflectanceCurve> make_working_space_curve(const Material& material,
                                                           ColorSpace working_space);
// The same with the gamut mapping applied: what the coefficients are fitted to.
std::unique_ptr<ReflectanceCurve> make_reflectance_curve(const Material& material,
                                                         const ColorOptions& color = {});

// The metal of a coated material against its coat, at its own cosine (the index relative to the
// coat), in the working space: per channel in the material's input space, then converted.
// Requires material.coat.
std::unique_ptr<ReflectanceCurve> make_metal_in_coat_curve(const Material& material,
                                                           ColorSpace working_space);
// The same seen through the coat from air (UnderCoatCurve): what its coefficients are fitted to.
std::unique_ptr<ReflectanceCurve> make_under_coat_curve(const Material& material,
                                                        ColorSpace working_space);

CompiledMaterial compile_material(const Material& material, const runtime::BasisView& basis,
                                  const ColorOptions& color = {});

// Above this max |F - exact| (2.5x the worst of the 23 measured metals with the paper basis,
// 8x with the default; docs/accuracy.md) a fit is called poor.
inline constexpr double kPoorFitMaxError = 0.05;

// Above this midpoint error a thickness per pixel's stack (BakedFilmStack::thickness_error) is
// called poor: the target for F, 0.01.
inline constexpr double kPoorFilmStackError = 0.01;

// A warning, at the material's name, when the decomposition misses the exact curve by more than
// kPoorFitMaxError: the measured error, Schlick's and F82-tint's beside it, and what to try; or
// when a thickness per pixel's stack misses its films by more than kPoorFilmStackError.
void warn_if_poor_fit(const CompiledMaterial& compiled, Diagnostics& diagnostics);

// A note, at the material's name, when its curve leaves [0, 1] in the working space: the extent,
// and what --gamut-mapping desaturate would keep.
void note_if_out_of_unit_range(const CompiledMaterial& compiled, Diagnostics& diagnostics);

}  // namespace matc
