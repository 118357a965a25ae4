// The C++ text of a SPIR-V module kept in a generated source (src/generated/): one constexpr array
// of its words, eight a line.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace matc {

// "constexpr std::uint32_t <name>[<size>] = {\n  0x07230203, ...\n};\n\n".
std::string word_array_source(std::string_view name, std::span<const std::uint32_t> words);

}  // namespace matc
