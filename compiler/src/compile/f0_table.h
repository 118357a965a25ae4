// The F0 table of a textured metal whose curve is not linear in F0 (matc/runtime/f0_table.h): a
// glTF metal's base colour texture under an edge colour or a clear coat (docs/gltf.md).
#pragma once

#include <span>

#include "compile/compile.h"
#include "matc/runtime/f0_table.h"

namespace matc {

// Whether `material` has an F0 table under `color`: an F82-tint metal (what glTF import writes)
// whose channels no matrix or gamut mapping mixes (each entry compiles all three channels at one
// F0, so a channel's coefficients must be its own).
bool has_f0_table(const Material& material, const ColorOptions& color);

// Each entry compiled as compile_material compiles the material with F0 = the entry's on every
// channel (its edge colour, coat and every other input kept): the coefficients in air and, for a
// coated metal, under the coat. Throws std::logic_error where has_f0_table is false.
runtime::F0Table compile_f0_table(const Material& material, const runtime::BasisView& basis,
                                  const ColorOptions& color);

// How closely a table follows the compile, over `f0s` (each the F0 of every channel): the largest
// |F from the table's interpolated coefficients - F from compile_material at that F0| over 257
// cosines (a coated metal's both lobes summed), and the largest error of those compiles against
// the exact curve (the coated metal's layered one), for scale.
struct F0TableError {
  double table = 0.0;
  double fit = 0.0;
};
F0TableError measure_f0_table(const Material& material, const runtime::BasisView& basis,
                              const ColorOptions& color, std::span<const double> f0s);

}  // namespace matc
