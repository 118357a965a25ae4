// Baking the RGBA lookup table bbar_i(NdotV, roughness) (layout: matc/runtime/lut.h).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "matc/runtime/basis.h"
#include "matc/runtime/lut.h"

namespace matc {

// 128: the table's reconstruction error stays well under the basis' own (docs/accuracy.md).
inline constexpr std::size_t kDefaultLutSize = 128;
inline constexpr std::size_t kDefaultLutSamples = 1024;
inline constexpr std::size_t kMinLutSize = 2;
inline constexpr std::size_t kMaxLutSize = 4096;
inline constexpr std::size_t kMaxLutSamples = 1u << 20;

struct LutOptions {
  std::size_t size = kDefaultLutSize;        // width = height, in texels
  std::size_t samples = kDefaultLutSamples;  // Hammersley points per texel
  unsigned threads = 0;                      // 0: one per hardware thread
};

// An owning table; the same inputs give the same bytes whatever the thread count.
struct Lut {
  std::size_t size = 0;
  std::size_t samples = 0;
  std::vector<float> texels;  // size * size * 4, rows by roughness, RGBA = bbar_0..bbar_3

  runtime::LutView view() const { return {size, texels}; }
};

// The split-sum averages bbar_0..bbar_3 of `basis` at one (NdotV, roughness).
std::array<double, runtime::kBasisSize> preintegrate_basis(const runtime::BasisView& basis,
                                                           double ndotv, double roughness,
                                                           std::size_t samples);

// Throws std::invalid_argument when size or samples are outside the limits above.
Lut preintegrate_lut(const runtime::BasisView& basis, const LutOptions& options = {});
// The tables of several bases over the same GGX samples (each texel's sampling shared): each one
// bit for bit preintegrate_lut's of its basis, in less time than one call each.
std::vector<Lut> preintegrate_luts(std::span<const runtime::BasisView> bases,
                                   const LutOptions& options = {});

}  // namespace matc
