// Reading a decimal number from text, the same in every build of the library.
#pragma once

#include <optional>
#include <string_view>

namespace matc {

// The whole of `text` as a double (one leading '+' allowed), rounded as std::from_chars rounds;
// nothing when any of it is not the number or the number is past the largest double.
std::optional<double> parse_number(std::string_view text);

}  // namespace matc
