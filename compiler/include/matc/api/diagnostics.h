// What went wrong with an input, located: the public face's diagnostics (docs/api.md).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace matc::api {

struct Diagnostic {
  std::string severity;    // "error", "warning" or "note"
  std::string path;        // the input's path or name
  std::size_t line = 0;    // 1-based; 0: the whole input
  std::size_t column = 0;  // 1-based byte column
  std::string field;       // e.g. "artistic.reflectivity[1]"; may be empty
  std::string message;     // what is wrong
  std::string allowed;     // what would be accepted; may be empty
  std::string text;        // the line the CLI prints: "path:line:col: error: field: message; ..."
};

// An input with errors. what() is the CLI's lines, one per diagnostic; every part that came from
// the input is escaped (no control bytes), so a message is safe to print or show in a page.
class MaterialError : public std::runtime_error {
 public:
  explicit MaterialError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

// Text from an input made safe to print, as every diagnostic quotes it: control bytes, bytes that
// are not UTF-8 and the Unicode controls that reorder text escaped (\n, \xNN, \u{NNNN}); a
// backslash is left as it is. A face that echoes a path or a name from its input prints this.
std::string printable(std::string_view text);
// printable(text), cut after `max_bytes` bytes of the input with "..." and the text's length.
std::string echoed(std::string_view text, std::size_t max_bytes = 64);

}  // namespace matc::api
