// Compiling a material: its coefficients c_0..c_3 per RGB channel against a basis, how close they
// come to the exact curve, and every curve the shaders or the comparisons compute, evaluated on
// the CPU exactly as the shaders do (docs/api.md).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "matc/api/diagnostics.h"
#include "matc/api/material.h"

namespace matc {
struct CompiledMaterial;
}

namespace matc::api {

class PreintegratedTable;

// Rows R, G, B; columns c_0..c_3.
using CoefficientRows = std::array<std::array<double, 4>, 3>;

// The names the options take are the CLI's (--basis, --color-space, --gamut-mapping); empty means
// the default. A name outside them throws std::invalid_argument naming the option and the names.
struct CompileOptions {
  // "auto" (the default: each material the shipped basis that holds its curve, docs/accuracy.md)
  // or one basis for every material ("powers", "f82", ...).
  std::string basis;
  std::string color_space;
  std::string gamut_mapping;
};
// The options' defaults by name: basis "auto" (a basis per material); where one basis is meant
// (tables, describe_basis), option_default("basis"), "powers".
CompileOptions default_compile_options();

// Max and RMS |F - exact| per channel over the accuracy samples: the decomposition's, Schlick's
// (exact F0) and F82-tint's (exact F0 and F(1/7)).
struct Accuracy {
  std::size_t samples = 0;
  Rgb max_error{}, rms_error{};
  Rgb schlick_max_error{}, schlick_rms_error{};
  Rgb f82_tint_max_error{}, f82_tint_rms_error{};
};

// A metal's complex index per channel, and Gulbrandsen's reflectivity and edge tint for it.
struct ComplexIor {
  Rgb n{}, k{};
};
struct ArtisticParameters {
  Rgb reflectivity{}, edge_tint{};
};
// Gulbrandsen's mapping per channel, both ways. ior_from_artistic takes a reflectivity in [0, 1)
// and an edge tint in [0, 1]; artistic_from_ior an n > 0 and a k >= 0, finite. Other values throw
// std::invalid_argument naming the field and the channel. artistic_from_ior is the exact inverse:
// an index outside the artistic range gets an edge tint outside [0, 1] (the shaders' version,
// runtime::artistic_from_ior, clamps it).
ComplexIor ior_from_artistic(const ArtisticParameters& artistic);
ArtisticParameters artistic_from_ior(const ComplexIor& ior);

// A `coat` block compiled (docs/coating.md).
struct Coat {
  double weight = 1.0;
  double ior = 1.5;
  double roughness = 0.0;
  Rgb color{1.0, 1.0, 1.0};
  CoefficientRows under_coat_coefficients{};  // the metal seen through the coat
  std::array<double, 4> coat_coefficients{};  // the coat's own Fresnel
  Rgb layered_max_error{};                    // the shaders' layering against the exact one
};

// A filmed metal's own table (docs/thin-film.md): width x height RGBA texels, row after row, as
// <name>.film.<ext> holds them at f32. Row 0 is F over sqrt(mu), rows 1 to 17 the preintegrated F
// over sqrt(NdotV) and sqrt((roughness - 0.05) / 0.95); sample it with the shaders'
// matc_film_fresnel_texcoord and matc_film_preintegrated_texcoord.
struct FilmTable {
  std::size_t width = 0;
  std::size_t height = 0;
  std::vector<float> texels;
};

class CompiledMaterial {
 public:
  const Material& material() const { return material_; }
  const std::string& name() const;
  std::string basis() const;  // its name, e.g. "powers"
  const CoefficientRows& coefficients() const;
  Rgb f0() const;               // the exact F at normal incidence
  Rgb f82() const;              // the exact F at mu = 1/7 (about 82 degrees)
  Rgb average_fresnel() const;  // the decomposed F's cosine-weighted average
  Accuracy accuracy() const;
  std::optional<Coat> coat() const;
  // A filmed metal's table, which its shaders sample for F and Fbar; none without a film.
  std::optional<FilmTable> film_table() const;
  // The working colour space and gamut mapping it was compiled in, by the options' names.
  std::string color_space() const;
  std::string gamut_mapping() const;
  // The metal's index and artistic parameters (none for a spectral material).
  std::optional<ComplexIor> ior() const;
  std::optional<ArtisticParameters> artistic() const;
  // How far the exact curve leaves the working gamut before any mapping (1: inside), and
  // whether the decomposed F is nonnegative at every cosine.
  double saturation() const;
  bool fresnel_nonnegative() const;
  // What <name>.json holds, less the inputs hash (which depends on the build's options).
  std::string json() const;
  // The material's diagnostics and the compile's: a poor fit, a curve outside [0, 1].
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

  // Curves at cosines mu in [0, 1]: 3 values (R, G, B) per cosine. A cosine outside [0, 1] or
  // not a number throws std::invalid_argument naming `mu` and its index.
  // F as the shaders compute it (a coated material's both lobes summed; a filmed metal's from its
  // own table, docs/thin-film.md).
  std::vector<double> fresnel(std::span<const double> mu) const;
  // The same into `rgb`, 3 values per cosine (std::invalid_argument for another size): no
  // allocation, for callers that evaluate in bulk.
  void fresnel(std::span<const double> mu, std::span<double> rgb) const;
  // The exact curve the coefficients were fitted to (a coated material's layered curve).
  std::vector<double> exact(std::span<const double> mu) const;
  // Schlick's with the exact F0, and Hoffman's F82-tint with the exact F0 and F(1/7).
  std::vector<double> schlick(std::span<const double> mu) const;
  std::vector<double> f82_tint(std::span<const double> mu) const;
  // A coated material's lobes at mu (throws std::logic_error for a bare one): the base lobe's
  // 3 values per cosine, and the coat lobe's one.
  struct Lobes {
    std::vector<double> base;
    std::vector<double> coat;
  };
  Lobes coated_fresnel(std::span<const double> mu) const;
  // The preintegrated F (split sum, the default table of this basis, baked on first use) at
  // pairs (NdotV, roughness), both in [0, 1] and of one length: 3 values per pair. A filmed
  // metal's comes from its own table, whichever table is given.
  std::vector<double> fbar(std::span<const double> ndotv, std::span<const double> roughness) const;
  // The same from `table` (matc/api/tables.h; native builds), which must integrate this
  // material's basis (std::invalid_argument otherwise).
  std::vector<double> fbar(std::span<const double> ndotv, std::span<const double> roughness,
                           const PreintegratedTable& table) const;
  // Both into `rgb`, 3 values per pair (std::invalid_argument for another size).
  void fbar(std::span<const double> ndotv, std::span<const double> roughness,
            std::span<double> rgb) const;
  void fbar(std::span<const double> ndotv, std::span<const double> roughness,
            const PreintegratedTable& table, std::span<double> rgb) const;
  static constexpr std::size_t kReferenceSamples = 1u << 16;
  // The exact split-sum integral of the exact curve at the same pairs: Monte Carlo with
  // `samples` GGX samples per pair (in [16, 2^26]), no basis, no table; a coated material's
  // lobes layered as matc eval's Fbar_reference. Native builds.
  std::vector<double> fbar_reference(std::span<const double> ndotv,
                                     std::span<const double> roughness,
                                     std::size_t samples = kReferenceSamples) const;

  // The library's own value, for the library's implementation.
  const matc::CompiledMaterial& value() const { return *value_; }
  struct Evaluation;
  CompiledMaterial(Material material, std::shared_ptr<const matc::CompiledMaterial> value,
                   std::shared_ptr<const Evaluation> evaluation,
                   std::vector<Diagnostic> diagnostics);

 private:
  Material material_;
  std::shared_ptr<const matc::CompiledMaterial> value_;
  std::shared_ptr<const Evaluation> evaluation_;
  std::vector<Diagnostic> diagnostics_;
};

CompiledMaterial compile(const Material& material, const CompileOptions& options = {});

// F at cosines mu for any coefficients (a coefficient table's, a texture's) as the shaders compute
// it with `basis` (one basis; empty: "powers"): 3 values per cosine. Each coefficient must be
// finite.
std::vector<double> fresnel_from_coefficients(const CoefficientRows& coefficients,
                                              std::span<const double> mu,
                                              std::string_view basis = {});

}  // namespace matc::api
