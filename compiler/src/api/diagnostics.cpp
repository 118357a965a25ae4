#include "matc/api/diagnostics.h"

#include <string>

#include "base/echoed_text.h"
#include "public_diagnostics.h"

namespace matc::api {
namespace {

std::string lines_of(const std::vector<Diagnostic>& diagnostics) {
  std::string text;
  for (const Diagnostic& diagnostic : diagnostics) {
    if (!text.empty()) text += '\n';
    text += diagnostic.text;
  }
  return text;
}

}  // namespace

MaterialError::MaterialError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(lines_of(diagnostics)), diagnostics_(std::move(diagnostics)) {}

std::vector<Diagnostic> public_diagnostics(const Diagnostics& diagnostics) {
  std::vector<Diagnostic> out;
  out.reserve(diagnostics.items().size());
  for (const matc::Diagnostic& item : diagnostics.items()) {
    // format_diagnostic escapes every part; the parts are escaped the same way for a caller
    // that shows them apart.
    out.push_back({std::string(severity_name(item.severity)), printable(item.location.path),
                   item.location.line, item.location.column, printable(item.field),
                   printable(item.message), printable(item.allowed), format_diagnostic(item)});
  }
  return out;
}

std::string printable(std::string_view text) {
  return matc::printable(text);
}

std::string echoed(std::string_view text, std::size_t max_bytes) {
  return matc::echoed(text, max_bytes);
}

void throw_if_errors(const Diagnostics& diagnostics) {
  if (diagnostics.has_errors()) throw MaterialError(public_diagnostics(diagnostics));
}

}  // namespace matc::api
