#include "formats/glb_container.h"

#include <cstdint>

#include <fmt/format.h>

namespace matc {
namespace {

constexpr std::uint32_t kJsonChunk = 0x4E4F534Au;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942u;   // "BIN\0"

std::uint32_t little_endian_u32(std::string_view bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i)
    value |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[offset + i])) << (8 * i);
  return value;
}

void append_u32(std::string& out, std::uint64_t value) {
  for (std::size_t i = 0; i < 4; ++i)
    out.push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
}

}  // namespace

std::string glb_layout_problem(std::string_view bytes) {
  if (bytes.size() < 20)
    return fmt::format("{} bytes: shorter than a GLB header and a chunk header (20 bytes)",
                       bytes.size());
  if (bytes.substr(0, 4) != "glTF") return "does not start with the GLB magic 'glTF'";
  if (const std::uint32_t version = little_endian_u32(bytes, 4); version != 2)
    return fmt::format("GLB version {}; matc reads version 2", version);
  if (const std::uint32_t length = little_endian_u32(bytes, 8); length != bytes.size())
    return fmt::format("the GLB header says {} bytes, the file has {} (truncated or padded)",
                       length, bytes.size());
  const std::uint64_t json_length = little_endian_u32(bytes, 12);
  if (little_endian_u32(bytes, 16) != kJsonChunk) return "the first GLB chunk is not JSON";
  if (json_length == 0 || json_length % 4 != 0)
    return fmt::format("the JSON chunk's length {} is not a positive multiple of 4", json_length);
  if (20 + json_length > bytes.size())
    return fmt::format("the JSON chunk ({} bytes) runs past the end of the file", json_length);
  const std::uint64_t rest = bytes.size() - 20 - json_length;
  if (rest == 0) return {};
  if (rest < 8) return "a chunk header after the JSON chunk is truncated";
  const auto bin_header = static_cast<std::size_t>(20 + json_length);  // inside the file (above)
  const std::uint64_t bin_length = little_endian_u32(bytes, bin_header);
  if (little_endian_u32(bytes, bin_header + 4) != kBinChunk)
    return "the second GLB chunk is not BIN";
  if (bin_length % 4 != 0)
    return fmt::format("the BIN chunk's length {} is not a multiple of 4", bin_length);
  if (28 + json_length + bin_length > bytes.size())
    return fmt::format("the BIN chunk ({} bytes) runs past the end of the file", bin_length);
  return {};
}

GlbParts glb_parts(std::string_view bytes) {
  const std::size_t json_length = little_endian_u32(bytes, 12);
  std::string_view json = bytes.substr(20, json_length);
  // The chunk is padded with spaces (some writers used NUL bytes) to 4 bytes.
  while (!json.empty() && (json.back() == ' ' || json.back() == '\0'))
    json.remove_suffix(1);
  return {json, bytes.substr(20 + json_length)};
}

std::string glb_file(std::string_view json, std::string_view after_json) {
  const std::size_t padded = (json.size() + 3) / 4 * 4;
  std::string out;
  out.reserve(20 + padded + after_json.size());
  out.append("glTF");
  append_u32(out, 2);
  append_u32(out, 20 + padded + after_json.size());
  append_u32(out, padded);
  append_u32(out, kJsonChunk);
  out.append(json);
  out.append(padded - json.size(), ' ');
  out.append(after_json);
  return out;
}

}  // namespace matc
