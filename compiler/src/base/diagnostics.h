// Compiler-style diagnostics: `path:line:col: error: <field>: <what is wrong>; <what is allowed>`.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace matc {

enum class Severity { error, warning, note };

// 1-based line and byte column; line 0 means the diagnostic is about the whole file.
struct SourceLocation {
  std::string path;
  std::size_t line = 0;
  std::size_t column = 0;
};

struct Diagnostic {
  Severity severity = Severity::error;
  SourceLocation location;
  std::string field;    // dotted field path such as "artistic.reflectivity[1]"; may be empty
  std::string message;  // what is wrong
  std::string allowed;  // what would be accepted; may be empty
};

std::string_view severity_name(Severity severity);

class Diagnostics;
// When `diagnostics` hold errors or warnings located in `referenced_path`, adds after the last of
// them a note at `where` (the place that names that file): "<field>: '<path>' is read here".
void note_referenced_from(Diagnostics& diagnostics, const std::string& referenced_path,
                          const SourceLocation& where, const std::string& field);
std::string format_diagnostic(const Diagnostic& diagnostic);

// Collects every diagnostic of one compile so that all problems are reported at once.
class Diagnostics {
 public:
  void add(Diagnostic diagnostic) { items_.push_back(std::move(diagnostic)); }
  void error(SourceLocation location, std::string field, std::string message,
             std::string allowed = {});
  void warning(SourceLocation location, std::string field, std::string message,
               std::string allowed = {});
  void note(SourceLocation location, std::string field, std::string message,
            std::string allowed = {});
  void append(const Diagnostics& other);

  bool has_errors() const;
  std::size_t error_count() const;
  const std::vector<Diagnostic>& items() const { return items_; }
  std::vector<Diagnostic>& items() { return items_; }

 private:
  std::vector<Diagnostic> items_;
};

// Maps byte offsets in a text to 1-based line and column.
class TextLocator {
 public:
  TextLocator(std::string path, std::string_view text);
  SourceLocation at(std::size_t offset) const;
  SourceLocation whole_file() const { return {path_, 0, 0}; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<std::size_t> line_starts_;
};

}  // namespace matc
