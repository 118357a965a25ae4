#include "print_diagnostics.h"

#include <atomic>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

namespace matc::cli {
namespace {

// Chosen once from the command line, before any work starts.
std::atomic<DiagnosticsFormat> chosen_format{DiagnosticsFormat::text};

std::string as_json_line(const api::Diagnostic& diagnostic) {
  const nlohmann::ordered_json object = {
      {"file", diagnostic.path},      {"line", diagnostic.line},
      {"column", diagnostic.column},  {"severity", diagnostic.severity},
      {"field", diagnostic.field},    {"message", diagnostic.message},
      {"allowed", diagnostic.allowed}};
  // Bytes that are not UTF-8 (from a bad input's name, say) become U+FFFD instead of throwing.
  return object.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace

void set_diagnostics_format(DiagnosticsFormat format) {
  chosen_format = format;
}

DiagnosticsFormat diagnostics_format() {
  return chosen_format;
}

void print_diagnostics(const std::vector<api::Diagnostic>& diagnostics, std::size_t from) {
  const bool json = chosen_format == DiagnosticsFormat::json;
  for (std::size_t i = from; i < diagnostics.size(); ++i)
    fmt::print(stderr, "{}\n", json ? as_json_line(diagnostics[i]) : diagnostics[i].text);
}

}  // namespace matc::cli
