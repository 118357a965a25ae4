// A filmed metal's own table (issue #67; docs/thin-film.md): the 4-term basis cannot carry a
// film's interference (thick films oscillate with the angle), so a filmed metal ships its curve
// as a 65 x 18 RGBA texture, <name>.film.<ext>: row 0 F at 65 nodes uniform in sqrt(mu), for
// direct light, and rows 1-17 the split sum's Fresnel factor Fbar over sqrt(NdotV) x
// sqrt((roughness - 0.05) / 0.95), for image light. Texel centres lie on the nodes; the shaders
// sample it bilinearly at matc_film_fresnel_texcoord(mu) and
// matc_film_preintegrated_texcoord(NdotV, roughness), and the functions below read it exactly as
// that sampler does, each input clamped to its axis (NaN read as 0).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "matc/runtime/fresnel.h"

namespace matc::runtime {

struct FilmTable {
  static constexpr std::size_t kCosineNodes = 65;
  static constexpr std::size_t kViewNodes = 65;
  static constexpr std::size_t kRoughnessNodes = 17;
  // The texture: a row of F above the rows of Fbar.
  static constexpr std::size_t kWidth = 65;
  static constexpr std::size_t kHeight = 1 + kRoughnessNodes;
  static_assert(kCosineNodes == kWidth && kViewNodes == kWidth);
  // Below it, the first row stands in (the lobe is narrower still).
  static constexpr double kMinRoughness = 0.05;

  std::array<Rgb, kCosineNodes> fresnel{};  // F at film_table_cosine(i)
  // Fbar at (film_table_view_cosine(i), film_table_roughness(j)): kViewNodes x kRoughnessNodes,
  // NdotV fastest.
  std::vector<Rgb> preintegrated;
};

// The nodes: mu = (i / 64)^2, NdotV = (i / 64)^2, roughness = 0.05 + 0.95 (j / 16)^2.
double film_table_cosine(std::size_t i);
double film_table_view_cosine(std::size_t i);
double film_table_roughness(std::size_t j);

// Where an input lies along its axis, in [0, 1]: sqrt(mu) (sqrt(NdotV)), and
// sqrt((roughness - 0.05) / 0.95).
double film_cosine_coordinate(double mu);
double film_roughness_coordinate(double roughness);

// The texture's texels, RGBA (A = 1), row after row from row 0: what <name>.film.<ext> holds.
std::vector<float> film_table_texels(const FilmTable& table);

// F for a direct light at mu = dot(V, H), as matc_fresnel_<name>.
Rgb film_fresnel(const FilmTable& table, double mu);
// Fbar for image light at (NdotV, roughness), as matc_fresnel_preintegrated_<name>.
// Requires preintegrated.size() == kViewNodes * kRoughnessNodes.
Rgb film_preintegrated(const FilmTable& table, double ndotv, double roughness);

}  // namespace matc::runtime
