#include "base/csv_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "base/number_text.h"

namespace matc {
namespace {

constexpr std::size_t kMaxReportedRowErrors = 10;

struct Field {
  std::string_view text;
  std::size_t offset;
};

std::vector<Field> split_fields(std::string_view line, std::size_t line_offset) {
  std::vector<Field> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    std::string_view field = line.substr(start, end - start);
    std::size_t lead = 0;
    while (lead < field.size() && std::isspace(static_cast<unsigned char>(field[lead])))
      ++lead;
    field.remove_prefix(lead);
    while (!field.empty() && std::isspace(static_cast<unsigned char>(field.back()))) {
      field.remove_suffix(1);
    }
    fields.push_back({field, line_offset + start + lead});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

std::string normalized_header(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (!std::isspace(static_cast<unsigned char>(c))) {
      out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  return out;
}

}  // namespace

std::optional<std::vector<CsvRow>> read_numeric_csv(std::string_view text, std::string_view header,
                                                    const TextLocator& locator,
                                                    Diagnostics& diagnostics) {
  const std::size_t columns =
      static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
  std::vector<CsvRow> rows;
  std::size_t errors = 0;
  bool first_content_line = true;
  std::size_t line_offset = 0;
  while (line_offset <= text.size()) {
    std::size_t line_end = text.find('\n', line_offset);
    if (line_end == std::string_view::npos) line_end = text.size();
    std::string_view line = text.substr(line_offset, line_end - line_offset);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::size_t this_offset = line_offset;
    line_offset = line_end + 1;

    const auto first_char = line.find_first_not_of(" \t");
    if (first_char == std::string_view::npos || line[first_char] == '#') continue;

    const auto fields = split_fields(line, this_offset);
    const bool numeric = parse_number(fields.front().text).has_value();
    if (first_content_line && !numeric) {
      first_content_line = false;
      if (normalized_header(line) != normalized_header(header)) {
        diagnostics.error(locator.at(this_offset), "header",
                          fmt::format("unexpected header '{}'", line),
                          fmt::format("expected '{}' (wavelengths in nanometres)", header));
        return std::nullopt;
      }
      continue;
    }
    first_content_line = false;

    CsvRow row;
    bool row_ok = fields.size() == columns;
    if (!row_ok && errors < kMaxReportedRowErrors) {
      diagnostics.error(locator.at(this_offset), "row", fmt::format("has {} fields", fields.size()),
                        fmt::format("each row holds {} numbers: {}", columns, header));
    }
    for (std::size_t i = 0; row_ok && i < fields.size(); ++i) {
      const auto value = parse_number(fields[i].text);
      if (!value) {
        row_ok = false;
        if (errors < kMaxReportedRowErrors) {
          diagnostics.error(locator.at(fields[i].offset), "value",
                            fmt::format("'{}' is not a finite number", fields[i].text),
                            "a decimal number such as 532.5 or 1.2e-3");
        }
        break;
      }
      row.values.push_back(*value);
      row.offsets.push_back(fields[i].offset);
    }
    if (!row_ok) {
      ++errors;
      continue;
    }
    rows.push_back(std::move(row));
  }
  if (errors > kMaxReportedRowErrors) {
    diagnostics.error(
        locator.whole_file(), "",
        fmt::format("{} more malformed rows not shown", errors - kMaxReportedRowErrors));
  }
  if (errors > 0) return std::nullopt;
  if (rows.empty()) {
    diagnostics.error(locator.whole_file(), "", "holds no data rows",
                      fmt::format("rows of '{}'", header));
    return std::nullopt;
  }
  return rows;
}

}  // namespace matc
