// What every diagnostic of every input must hold (docs/reliability.md, the hostile-input
// checklist), checked by the fuzzers on each input they try.
#pragma once

#include <string_view>

#include "matc/base/diagnostics.h"

namespace matc::fuzz {

// Each diagnostic prints as one line with no control byte: no input text can forge another line
// or send the terminal a control sequence.
inline void require_printable_diagnostics(const Diagnostics& diagnostics) {
  for (const Diagnostic& diagnostic : diagnostics.items()) {
    for (const char c : format_diagnostic(diagnostic)) {
      const auto byte = static_cast<unsigned char>(c);
      if (byte < 0x20 || byte == 0x7F) __builtin_trap();
    }
  }
}

// A text holding a NUL byte is never accepted (a parser that stops there reads another text).
inline void require_refused_if_nul(std::string_view text, bool accepted) {
  if (accepted && text.find('\0') != std::string_view::npos) __builtin_trap();
}

}  // namespace matc::fuzz
