// A textured metal whose curve is not linear in F0 (an edge colour, a clear coat: a glTF metal's
// base colour texture, docs/gltf.md) at a pixel: its coefficients, compiled at kF0TableEntries
// values of F0 and interpolated at the pixel's F0 per channel. The entries are spaced evenly in
// F0^(1/4): under a coat the metal's coefficients change fastest near F0 = 0, where a metal's index
// nears the coat's.
#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include "matc/runtime/fresnel.h"

namespace matc::runtime {

inline constexpr std::size_t kF0TableEntries = 33;

// Entry i holds each channel's coefficients at F0 = (i / (kF0TableEntries - 1))^4, every other
// input the material's.
struct F0Table {
  std::array<Coefficients, kF0TableEntries> in_air{};
  std::optional<std::array<Coefficients, kF0TableEntries>> under_coat;  // a coated metal's
};

// The F0 of entry i.
double f0_table_entry_f0(std::size_t entry);

// Per channel, entries linearly interpolated at F0^(1/4) (F0 clamped to [0, 1]; NaN reads as 0).
// The metal in air then takes c_0 = F0 and c_1 = 1 - F0 exactly (its curve's values at normal and
// grazing incidence); under the coat all four are interpolated (its grazing value is fitted).
Coefficients coefficients_from_f0_table(const F0Table& table, const Rgb& f0);
Coefficients under_coat_coefficients_from_f0_table(const F0Table& table, const Rgb& f0);

}  // namespace matc::runtime
