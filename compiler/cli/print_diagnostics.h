#pragma once

#include <cstddef>
#include <vector>

#include "matc/api/diagnostics.h"

namespace matc::cli {

// text: `path:line:col: error: field: problem; allowed`. json: one JSON object per line
// (JSON Lines) with file, line, column, severity, field, message, allowed, for tools.
enum class DiagnosticsFormat { text, json };
void set_diagnostics_format(DiagnosticsFormat format);
DiagnosticsFormat diagnostics_format();

// Writes each diagnostic, from the one at `from` on, on its own line to standard error, in the
// format set above.
void print_diagnostics(const std::vector<api::Diagnostic>& diagnostics, std::size_t from = 0);

}  // namespace matc::cli
