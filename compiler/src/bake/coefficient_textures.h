// Baking an asset's maps into coefficient textures (docs/baking.md): per texel and colour channel
// the coefficients c_0..c_3 of its Fresnel curve, then a mip chain computed in coefficient space.
//
// Layout: c_0 = F0 (the engine's base colour, linear; also written as an optional F0 texture)
// and c_1 = 1 - c_0 are implied, so two RGBA textures hold the rest: C2 = (c_2 of R, G, B, 1) and
// C3 = (c_3 of R, G, B, 1). The basis is linear in the coefficients, so a mip texel that averages
// coefficients holds exactly the average of its texels' Fresnel curves; averaging the maps (r, g)
// and solving again does not. The engine's base-colour mips must therefore be box averages of
// linear F0 over the same footprints (what the F0 texture holds) for the average to stay exact.
#pragma once

#include <cstddef>
#include <vector>

#include "bake/bake_inputs.h"
#include "matc/runtime/basis.h"

namespace matc {

inline constexpr std::size_t kCoefficientTextureChannels = 4;  // RGBA

// One mip level: RGBA floats, row-major.
struct CoefficientLevel {
  std::size_t width = 0;
  std::size_t height = 0;
  std::vector<float> f0;  // (c_0 of R, G, B, 1), with BakeOptions::f0
  std::vector<float> c2;  // (c_2 of R, G, B, 1)
  std::vector<float> c3;  // (c_3 of R, G, B, 1)
};

// How level 0 was solved: the basis' own per-material solve once per distinct (r, g) of 8-bit
// maps and constants (exact), or the coefficient table (16-bit and float maps, n and k maps).
enum class BakeSolve { exact, table };
std::string_view bake_solve_name(BakeSolve solve);

struct BakeOptions {
  runtime::BasisKind basis = runtime::kDefaultBasis;
  bool f0 = false;         // fill CoefficientLevel::f0 (else c_0 is the engine's base colour)
  bool error_map = false;  // fill BakedCoefficients::error
  unsigned threads = 0;    // 0: one per hardware thread; the result does not depend on it
};

struct BakedCoefficients {
  runtime::BasisKind basis = runtime::kDefaultBasis;
  std::vector<CoefficientLevel> levels;  // level 0 (the maps' size) down to 1 x 1
  BakeSolve solve = BakeSolve::exact;
  std::size_t solved_pairs = 0;  // distinct (r, g) solved (exact); 0 for the table
  // Level 0: per texel, the largest |F - exact| over cosines and channels (with error_map), and
  // its maximum over the texture (always for the exact solve).
  std::vector<float> error;
  double max_error = 0.0;
  // Level-0 texels whose error is above kPoorFitMaxError (the compile's poor-fit warning), and
  // the worst texel (row-major index); known for the exact solve, and with error_map.
  std::size_t poor_fit_texels = 0;
  std::size_t worst_texel = 0;
};

BakedCoefficients bake_coefficients(const BakeInputs& inputs, const BakeOptions& options);

// The next mip level of an RGBA image: each texel the area-weighted average of the texels its
// footprint covers (2 x 2 for even sizes, fractional weights across odd ones).
std::vector<float> downsample_level(const std::vector<float>& texels, std::size_t width,
                                    std::size_t height, std::size_t next_width,
                                    std::size_t next_height, unsigned threads = 0);

// Number of levels of a full chain: floor(log2(max(width, height))) + 1.
std::size_t mip_level_count(std::size_t width, std::size_t height);

// A full mip chain of an RGBA image: `level0` (width x height), then each level downsampled from
// the one before (downsample_level), each half the size rounded down, down to 1 x 1.
std::vector<std::vector<float>> mip_chain(std::vector<float> level0, std::size_t width,
                                          std::size_t height, unsigned threads = 0);

// One texel's channel of a baked level (baked with f0): c_0 = F0, c_1 = 1 - c_0, c_2, c_3.
runtime::ChannelCoefficients level_coefficients(const CoefficientLevel& level, std::size_t x,
                                                std::size_t y, std::size_t channel);

}  // namespace matc
