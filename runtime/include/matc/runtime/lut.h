// The preintegrated lookup table bbar_i(NdotV, roughness) and how shaders sample it.
//
// Layout: a square RGBA float texture, `size` x `size` texels, rows (y) indexed by roughness and
// columns (x) by NdotV; channel i holds bbar_i, the split-sum average of basis element b_i.
// Texel (x, y) holds the integral at
//     NdotV     = (x / (size - 1))^2      (axis u = sqrt(NdotV): more texels near grazing)
//     roughness =  y / (size - 1)         (perceptual; GGX alpha = roughness^2)
// i.e. texel centres sit exactly on the ends of both ranges. A sampler with linear filtering and
// clamp-to-edge addressing reads the table at
//     texcoord = (u * (size - 1) + 0.5) / size   per axis,
// which is what sample_lut() below reproduces on the CPU.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"

namespace matc::runtime {

// Table axis u in [0, 1] for a cosine, and back.
double lut_u_from_ndotv(double ndotv);
double lut_ndotv_from_u(double u);

// A non-owning view of a table in the layout above (row-major, 4 floats per texel).
struct LutView {
  std::size_t size = 0;
  std::span<const float> texels;  // size * size * 4

  std::array<float, kBasisSize> texel(std::size_t x, std::size_t y) const;
};

// bbar_0..bbar_3 at (NdotV, roughness), bilinearly filtered exactly as a GPU sampler would with the
// texture coordinates given above (inputs clamped to [0, 1]).
std::array<double, kBasisSize> sample_lut(const LutView& lut, double ndotv, double roughness);

// Fbar = sum_i c_i bbar_i per channel: the preintegrated Fresnel, one fetch.
Rgb evaluate_fbar(const Coefficients& coefficients, const LutView& lut, double ndotv,
                  double roughness);

}  // namespace matc::runtime
