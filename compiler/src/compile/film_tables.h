// A filmed metal's own representation (issue #67), which the 4-term basis cannot carry (thick
// films oscillate with the angle): F at 64 nodes uniform in sqrt(mu), read linearly, for direct
// light, and the split sum's Fresnel factor Fbar over sqrt(NdotV) x sqrt(roughness - 0.05) at
// 65 x 17 nodes, read bilinearly, for image light. Fbar is baked from the F table as matc bakes
// its own table (GGX visible normals, Smith height-correlated). The sizes are those
// docs/accuracy.md measured ("A film's curve as a table", "A film's image light"): F within
// 0.0026 and Fbar within 0.0041 of the exact film's over the measured metals and films of 0-1000
// nm; FilmTables.* holds them on a few. The shaders that read them are to come.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "optics/reflectance_curve.h"

namespace matc {

struct FilmTables {
  static constexpr std::size_t kCosineNodes = 64;
  static constexpr std::size_t kViewNodes = 65;
  static constexpr std::size_t kRoughnessNodes = 17;
  // Below it, the first row stands in (the lobe is narrower still).
  static constexpr double kMinRoughness = 0.05;

  std::array<Rgb, kCosineNodes> fresnel{};  // F at mu = (i / 63)^2
  // Fbar at NdotV = (i / 64)^2 and roughness 0.05 + 0.95 (j / 16)^2: kViewNodes x
  // kRoughnessNodes, NdotV fastest.
  std::vector<Rgb> preintegrated;

  // F at cosine mu (clamped to [0, 1]), linearly between nodes.
  Rgb fresnel_at(double mu) const;
  // Fbar at (NdotV, roughness), each clamped to the table, bilinearly between nodes.
  Rgb preintegrated_at(double ndotv, double roughness) const;
};

// The node cosines and roughnesses.
double film_table_cosine(std::size_t i);
double film_table_view_cosine(std::size_t i);
double film_table_roughness(std::size_t j);

// The tables of `curve` (a filmed metal's exact curve), each Fbar node a split sum of the F table
// over `samples` visible normals.
FilmTables bake_film_tables(const ReflectanceCurve& curve, std::size_t samples = 1024);

}  // namespace matc
