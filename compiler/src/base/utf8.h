// Decoding one UTF-8 sequence, strictly (RFC 3629): what the diagnostics' escaping and the XML
// well-formedness check both need to know of a byte string.
#pragma once

#include <cstddef>
#include <string_view>

namespace matc {

// The length of the UTF-8 sequence at `text[at]` (1 to 4) with its code point, or 0 when the
// bytes there are not UTF-8 (a stray continuation byte, a truncated sequence, an overlong form, a
// surrogate, a value past U+10FFFF).
std::size_t utf8_sequence(std::string_view text, std::size_t at, char32_t& code_point);

}  // namespace matc
