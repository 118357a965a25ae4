// C++ array literals for the generated headers and table sources: every float printed so that it
// reads back bit for bit.
#pragma once

#include <string>
#include <string_view>

#include <fmt/format.h>

namespace matc::formats {

// Shortest round-trip float literal.
inline std::string float_literal(float value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text + "f";
}

// `<qualifiers> float NAME[N] = {...};` with `per_line` values a line.
template <typename Values>
void append_float_array(std::string& out, std::string_view qualifiers, std::string_view name,
                        const Values& values, std::size_t per_line) {
  out += fmt::format("{} float {}[{}] = {{\n", qualifiers, name, values.size());
  std::size_t column = 0;
  for (const auto value : values) {
    out += column == 0 ? "    " : " ";
    out += float_literal(static_cast<float>(value)) + ",";
    if (++column == per_line) {
      out += "\n";
      column = 0;
    }
  }
  if (column != 0) out += "\n";
  out += "};\n\n";
}

}  // namespace matc::formats
