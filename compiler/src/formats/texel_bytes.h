// Little-endian byte encoding shared by the LUT file writers.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "formats/table_format.h"

namespace matc::formats {

void put_u16(std::string& out, std::uint16_t value);
void put_u32(std::string& out, std::uint32_t value);
void put_u64(std::string& out, std::uint64_t value);
void pad_to(std::string& out, std::size_t alignment);

// A float rounded to IEEE half precision (round to nearest even), as a float.
float round_to_half(float value);

// Bytes per texel component in the given precision (2 or 4).
std::size_t component_bytes(LutPrecision precision);

// Every texel component, tightly packed, in the given precision, written to `destination`
// (component_bytes(precision) * texels.size() bytes).
void write_texel_bytes(std::span<const float> texels, LutPrecision precision, char* destination);
std::string texel_bytes(std::span<const float> texels, LutPrecision precision);

}  // namespace matc::formats
