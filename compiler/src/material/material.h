// A validated material: what a material file says, with its spectral data loaded.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "base/diagnostics.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"
#include "optics/color_space.h"
#include "optics/spectrum.h"

namespace matc {

using runtime::Rgb;

// Gulbrandsen 2014 reflectivity r in [0, 1) and edge tint g in [0, 1] per channel.
struct ArtisticInput {
  Rgb reflectivity{};
  Rgb edge_tint{};
};

// Complex index of refraction n + i k per channel.
struct IorInput {
  Rgb n{};
  Rgb k{};
};

// Measured n(lambda), k(lambda): a shipped preset or a CSV file.
struct SpectralInput {
  std::string preset;         // preset symbol such as "Au"; empty when `file` is used
  std::string file;           // the path as written in the material; empty when `preset` is used
  std::string resolved_file;  // `file` resolved against the material's folder
  std::string file_bytes;     // that file as read (it is part of the outputs' inputs hash)
  Spectrum spectrum;
};

// The OpenPBR / Adobe Standard Material metal: reflectance F0 at normal incidence and the tint that
// scales Schlick's curve at mu = 1/7 (about 82 degrees), each in [0, 1] per channel.
struct F82TintInput {
  Rgb f0{};
  Rgb tint{};
};

using MaterialModel = std::variant<ArtisticInput, IorInput, SpectralInput, F82TintInput>;

// A clear (or tinted) dielectric coat over the metal, named and defaulted as OpenPBR's coat_*
// (docs/coating.md): what is absent from a `coat` block takes these values, except the weight,
// which is 1 (a block that names a coat means one; OpenPBR's 0 is the absent coat).
// The lowest coat index a material may give (docs/coating.md: nearer 1 the coat's Fresnel is a
// spike at grazing that no basis made for Fresnel curves holds).
inline constexpr double kMinCoatIor = 1.05;

struct CoatInput {
  double weight = 1.0;     // coverage in [0, 1]
  double ior = 1.6;        // the coat's real index of refraction in [kMinCoatIor, 3]
  double roughness = 0.0;  // perceptual, in [0, 1]; the coat lobe's alpha = roughness^2
  // The coat's transmittance over the round trip at normal incidence, per channel in [0, 1]:
  // what it leaves of the base seen head on (Standard Surface's coat_color); longer paths at
  // other angles tint more (Beer's law).
  Rgb color{1.0, 1.0, 1.0};
};

// A thin dielectric film over the metal (heat-tinted titanium, anodised metals; docs/
// material-format.md), named as OpenPBR's thin_film_*: the film's real index, its thickness in nm
// and its coverage. The metal's F is the Airy sum of the film's reflections over the metal's own
// complex index (optics/thin_film.h), mixed with the bare metal's by the weight.
inline constexpr double kMinFilmIor = 1.0;
inline constexpr double kMaxFilmIor = 3.0;
inline constexpr double kMaxFilmThicknessNm = 2000.0;

struct FilmInput {
  FilmInput() = default;
  // A film of one thickness (the range's minimum is set apart, so that the three fields every
  // film has read as they always did).
  FilmInput(double weight_, double ior_, double thickness_nm_)
      : weight(weight_), ior(ior_), thickness_nm(thickness_nm_) {}

  double weight = 1.0;        // coverage in [0, 1]; a block that names a film means one
  double ior = 1.4;           // OpenPBR's thin_film_ior default, in [kMinFilmIor, kMaxFilmIor]
  double thickness_nm = 0.0;  // required, in [0, kMaxFilmThicknessNm]; 0 is the bare metal
  // A thickness per pixel (a thickness texture): the range's minimum, below thickness_nm, which is
  // then its maximum, and what a consumer without the texture takes (as glTF's
  // iridescenceThicknessMaximum). Absent: one thickness.
  std::optional<double> thickness_minimum_nm;
};

struct Material {
  std::string name;  // validated identifier, see docs/material-format.md
  MaterialModel model;
  std::optional<double> roughness;  // perceptual; alpha = roughness^2
  std::string source_path;          // the material file as named on the command line
  SourceLocation name_location;     // where the name is written, for batch-level diagnostics
  std::string source_text;          // the JSON as parsed: outputs hash it, never re-read
  // The space the model's RGB values are written in ("color_space"); absent: the build's working
  // space. Spectral materials have no RGB values and ignore it.
  std::optional<ColorSpace> color_space;
  std::optional<CoatInput> coat;  // absent: the metal is bare, seen from air
  std::optional<FilmInput> film;  // absent: no film on the metal
  // The basis the file pins ("basis": one of the per-material layers, compile/basis_choice.h);
  // absent: the build's rule chooses. `--basis NAME` overrides both.
  std::optional<runtime::BasisKind> basis;
};

// "artistic", "ior", "spectral" or "f82_tint": the key that selects the model in a material file.
std::string_view model_key(const MaterialModel& model);

}  // namespace matc
