#include "texel_bytes.h"

#include <bit>

#include <Eigen/Core>

namespace matc::lut_bytes {

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

std::string texel_bytes(std::span<const float> texels, LutPrecision precision) {
  std::string out;
  out.reserve(texels.size() * (precision == LutPrecision::f16 ? 2 : 4));
  for (const float value : texels) {
    if (precision == LutPrecision::f16) {
      put_u16(out, Eigen::numext::bit_cast<std::uint16_t>(Eigen::half(value)));
    } else {
      put_u32(out, std::bit_cast<std::uint32_t>(value));
    }
  }
  return out;
}

}  // namespace matc::lut_bytes
