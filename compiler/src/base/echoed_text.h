// Input text that a diagnostic repeats (a field name, a value, a node name) goes through here, so
// no input can forge a diagnostic line, move the terminal's cursor or hide text: control bytes,
// invalid UTF-8 and the Unicode controls that reorder text are shown escaped, and long text is cut.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace matc {

// `text` with C0 and C1 control characters, DEL, bytes that are not UTF-8 and bidirectional
// controls (U+061C, U+200E-F, U+202A-E, U+2066-9) escaped as \n, \t, \r, \xNN or \u{NNNN}. A
// backslash is left as it is. The result holds no newline and is valid UTF-8.
std::string printable(std::string_view text);

// printable(text), cut after `max_bytes` bytes of the input with "..." and the text's length in
// bytes, for text a diagnostic quotes.
std::string echoed(std::string_view text, std::size_t max_bytes = 64);

}  // namespace matc
