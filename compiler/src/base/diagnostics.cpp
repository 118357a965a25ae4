#include "base/diagnostics.h"

#include <algorithm>

#include <fmt/format.h>

#include "base/echoed_text.h"

namespace matc {

std::string_view severity_name(Severity severity) {
  switch (severity) {
    case Severity::error:
      return "error";
    case Severity::warning:
      return "warning";
    case Severity::note:
      return "note";
  }
  return "error";
}

// One line whatever the parts hold: input text that reached a part unescaped (a path, a key)
// cannot start a line of its own or send the terminal a control sequence.
std::string format_diagnostic(const Diagnostic& diagnostic) {
  std::string out = printable(diagnostic.location.path);
  if (diagnostic.location.line > 0) {
    out += fmt::format(":{}:{}", diagnostic.location.line, diagnostic.location.column);
  }
  out += fmt::format(": {}: ", severity_name(diagnostic.severity));
  if (!diagnostic.field.empty()) out += printable(diagnostic.field) + ": ";
  out += printable(diagnostic.message);
  if (!diagnostic.allowed.empty()) out += "; " + printable(diagnostic.allowed);
  return out;
}

void Diagnostics::error(SourceLocation location, std::string field, std::string message,
                        std::string allowed) {
  add({Severity::error, std::move(location), std::move(field), std::move(message),
       std::move(allowed)});
}

void Diagnostics::warning(SourceLocation location, std::string field, std::string message,
                          std::string allowed) {
  add({Severity::warning, std::move(location), std::move(field), std::move(message),
       std::move(allowed)});
}

void Diagnostics::note(SourceLocation location, std::string field, std::string message,
                       std::string allowed) {
  add({Severity::note, std::move(location), std::move(field), std::move(message),
       std::move(allowed)});
}

void Diagnostics::append(const Diagnostics& other) {
  items_.insert(items_.end(), other.items_.begin(), other.items_.end());
}

bool Diagnostics::has_errors() const {
  return error_count() > 0;
}

std::size_t Diagnostics::error_count() const {
  return static_cast<std::size_t>(std::count_if(
      items_.begin(), items_.end(), [](const auto& d) { return d.severity == Severity::error; }));
}

TextLocator::TextLocator(std::string path, std::string_view text) : path_(std::move(path)) {
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') line_starts_.push_back(i + 1);
  }
}

SourceLocation TextLocator::at(std::size_t offset) const {
  const auto next_line = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line = static_cast<std::size_t>(next_line - line_starts_.begin());
  return {path_, line, offset - line_starts_[line - 1] + 1};
}

void note_referenced_from(Diagnostics& diagnostics, const std::string& referenced_path,
                          const SourceLocation& where, const std::string& field) {
  auto& items = diagnostics.items();
  const auto last = std::find_if(items.rbegin(), items.rend(), [&](const Diagnostic& d) {
    return d.location.path == referenced_path && d.severity != Severity::note;
  });
  if (last == items.rend()) return;
  items.insert(last.base(), Diagnostic{Severity::note, where, field,
                                       "'" + referenced_path + "' is read here", ""});
}

}  // namespace matc
