// The preintegrated tables of several bases side by side in one texture (`--basis auto`), so a
// shader still reads every material's bbar with one fetch: layer k's columns are
// [k size, (k + 1) size), and a texel's centre never lies on a seam, so linear filtering inside
// a layer never reads its neighbour (docs/lut.md, "A layer per basis").
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "lut/preintegrate.h"

namespace matc {

struct LutAtlas {
  std::size_t size = 0;       // one layer's width and the height, in texels
  std::size_t layers = 0;     // side by side along x
  std::vector<float> texels;  // (layers size) x size RGBA texels, rows by roughness

  std::size_t width() const { return size * layers; }
};

// The layers in order; all must share one size.
LutAtlas side_by_side(std::span<const Lut> layers);

}  // namespace matc
