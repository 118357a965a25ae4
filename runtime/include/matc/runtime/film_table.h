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

// Where a direct light's split sum reads the F row: the left node and the weight of the next, as
// film_fresnel interpolates them (a split sum of the table is linear in its nodes).
struct FilmNodePosition {
  std::size_t left = 0;
  double weight = 0.0;
};
FilmNodePosition film_cosine_position(double mu);

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

// A film whose thickness varies per pixel (a thickness texture, glTF's
// iridescenceThicknessTexture; docs/thin-film.md "A thickness per pixel"): the tables of N >= 2
// films of thicknesses uniform over [minimum_nm, maximum_nm], read with linear interpolation over
// the thickness too. The thickness is a coordinate t in [0, 1], as the texture's green channel:
// minimum + t (maximum - minimum) nanometres.
//
// Its texture (<name>.film.<ext>) is 65 x 18 N: rows 0 to N - 1 hold each slice's F row, so a
// direct light is one bilinear fetch over (sqrt(mu), thickness); then for each roughness node j
// the N rows N + j N + s hold slice s's Fbar row, so image light is two bilinear fetches over
// (sqrt(NdotV), thickness) at the roughness nodes either side, mixed. With N = 1 the layout is
// FilmTable's.
struct FilmStack {
  double minimum_nm = 0.0;
  double maximum_nm = 0.0;
  std::vector<FilmTable> slices;  // slice s at minimum + (maximum - minimum) s / (N - 1)
};

// How far inside the end slices a read stays, in slices (a texel of the texture's thickness axis):
// 1/1024, past a float texcoord's rounding in a texture 4,096 rows tall, and below 0.003 nm of
// film between slices 2.5 nm apart.
inline constexpr double kFilmStackInset = 1.0 / 1024.0;

// The texture's height, 18 N, and its texels, RGBA (A = 1), row after row from row 0.
std::size_t film_stack_height(const FilmStack& stack);
std::vector<float> film_stack_texels(const FilmStack& stack);
// The thickness of slice s in nanometres.
double film_stack_thickness(const FilmStack& stack, std::size_t s);

// F and Fbar at thickness coordinate `thickness` (clamped to [0, 1], NaN read as 0), as the
// shaders' MATC_FILM_STACK_* fetches read the texture.
Rgb film_stack_fresnel(const FilmStack& stack, double mu, double thickness);
Rgb film_stack_preintegrated(const FilmStack& stack, double ndotv, double roughness,
                             double thickness);
// The film table at thickness coordinate `thickness` as the stack reads it: its two slices there
// mixed node by node (the reads are linear in the nodes), so that whatever reads one film's table
// (area lights, glTF's metal-rough mix) reads the stack at that thickness.
FilmTable film_stack_table_at(const FilmStack& stack, double thickness);

}  // namespace matc::runtime
