// A GLB written byte by byte for tests, apart from matc's own writer (formats/glb_container.h):
// the 12-byte header, the JSON chunk padded with spaces, an optional BIN chunk, then `trailing`
// bytes as they are (another chunk, say).
#pragma once

#include <cstdint>
#include <string>

namespace matc::test {

inline std::string glb_bytes(std::string json, const std::string& bin = "",
                             const std::string& trailing = "") {
  while (json.size() % 4 != 0)
    json += ' ';
  std::string out;
  const auto u32 = [&out](std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
      out += static_cast<char>((v >> (8 * i)) & 0xffu);
  };
  const std::size_t length =
      12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()) + trailing.size();
  out += "glTF";
  u32(2);
  u32(static_cast<std::uint32_t>(length));
  u32(static_cast<std::uint32_t>(json.size()));
  out += "JSON";
  out += json;
  if (!bin.empty()) {
    u32(static_cast<std::uint32_t>(bin.size()));
    out += std::string("BIN\0", 4);
    out += bin;
  }
  out += trailing;
  return out;
}

}  // namespace matc::test
