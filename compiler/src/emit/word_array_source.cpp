#include "emit/word_array_source.h"

#include <fmt/format.h>

namespace matc {

std::string word_array_source(std::string_view name, std::span<const std::uint32_t> words) {
  std::string out = fmt::format("constexpr std::uint32_t {}[{}] = {{\n", name, words.size());
  for (std::size_t i = 0; i < words.size(); ++i) {
    out += fmt::format("{}{:#010x},", i % 8 == 0 ? "  " : " ", words[i]);
    if (i % 8 == 7 || i + 1 == words.size()) out += "\n";
  }
  out += "};\n\n";
  return out;
}

}  // namespace matc
