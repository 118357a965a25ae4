#include "formats/texel_bytes.h"

#include <algorithm>
#include <bit>

#include <Eigen/Core>

#include "base/parallel_rows.h"

namespace matc::formats {

void put_u16(std::string& out, std::uint16_t value) {
  for (int shift = 0; shift < 16; shift += 8)
    out.push_back(static_cast<char>(value >> shift));
}
void put_u32(std::string& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8)
    out.push_back(static_cast<char>(value >> shift));
}
void put_u64(std::string& out, std::uint64_t value) {
  for (int shift = 0; shift < 64; shift += 8)
    out.push_back(static_cast<char>(value >> shift));
}
void pad_to(std::string& out, std::size_t alignment) {
  while (out.size() % alignment != 0)
    out.push_back('\0');
}

float round_to_half(float value) {
  return static_cast<float>(Eigen::half(value));
}

std::size_t component_bytes(LutPrecision precision) {
  return precision == LutPrecision::f16 ? 2 : 4;
}

void write_texel_bytes(std::span<const float> texels, LutPrecision precision, char* destination) {
  const std::size_t size = component_bytes(precision);
  // Textures of `matc bake` hold hundreds of millions of values: converted in chunks on every
  // hardware thread (each chunk depends only on its own values, so the bytes do not).
  constexpr std::size_t kChunk = std::size_t{1} << 18;
  const std::size_t chunks = (texels.size() + kChunk - 1) / kChunk;
  fill_rows_in_parallel(chunks, chunks > 4 ? 0u : 1u, [&] {
    return [&](std::size_t chunk) {
      const std::size_t end = std::min(texels.size(), (chunk + 1) * kChunk);
      for (std::size_t i = chunk * kChunk; i < end; ++i) {
        const std::uint32_t bits =
            size == 2 ? Eigen::numext::bit_cast<std::uint16_t>(Eigen::half(texels[i]))
                      : std::bit_cast<std::uint32_t>(texels[i]);
        for (std::size_t b = 0; b < size; ++b)
          destination[i * size + b] = static_cast<char>(bits >> (8 * b));
      }
    };
  });
}

std::string texel_bytes(std::span<const float> texels, LutPrecision precision) {
  std::string out(texels.size() * component_bytes(precision), '\0');
  write_texel_bytes(texels, precision, out.data());
  return out;
}

}  // namespace matc::formats
