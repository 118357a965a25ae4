// What every diagnostic of every input must hold (docs/reliability.md, the hostile-input
// checklist), checked by the fuzzers on each input they try.
#pragma once

#include <string>
#include <string_view>

#include "base/diagnostics.h"
#include "compile/compile.h"
#include "material/document_import.h"

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

// What a document importer (MaterialX, glTF) returns: no material beside an error, and an error
// when it imports nothing unless `empty_is_valid` (glTF: an asset without a metal is a note),
// every diagnostic printable, every material one the parser accepts from its own JSON (`path`
// names it), and the first one compiled without a NaN (compiling is slow next to reading: one
// per input covers the paths).
inline void require_sound_import(const DocumentImport& imported, const std::string& path,
                                 bool empty_is_valid = false) {
  if (!imported.materials.empty() && imported.diagnostics.has_errors()) __builtin_trap();
  if (!empty_is_valid && imported.materials.empty() && !imported.diagnostics.has_errors())
    __builtin_trap();
  require_printable_diagnostics(imported.diagnostics);
  for (const ImportedMaterial& material : imported.materials) {
    const ParseResult reparsed = parse_material(material.json, path);
    if (!reparsed.material || reparsed.diagnostics.has_errors()) __builtin_trap();
    if (reparsed.material->name != material.material.name) __builtin_trap();
  }
  if (!imported.materials.empty()) {
    const auto compiled =
        compile_material(imported.materials.front().material, runtime::shipped_basis());
    for (const auto& channel : compiled.coefficients)
      for (const double c : channel)
        if (!(c == c)) __builtin_trap();  // no NaN
  }
}

}  // namespace matc::fuzz
