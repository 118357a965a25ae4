#include "located_json_reader.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "material/parse.h"  // material_name_problem
#include "suggestion.h"

namespace matc {

using nlohmann::json;

std::string Range::describe() const {
  return fmt::format("[{}, {}{}", min, max, max_inclusive ? "]" : ")");
}

std::string describe_type(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::string:
      return "a string";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    default:
      return "a number";
  }
}

std::string child(const std::string& pointer, std::string_view key) {
  return pointer + "/" + std::string(key);
}

std::optional<LocatedJson> parse_located_json_reporting(std::string_view text,
                                                        const TextLocator& locator,
                                                        Diagnostics& diagnostics) {
  auto parsed = parse_located_json(text);
  if (const auto* syntax = std::get_if<JsonSyntaxError>(&parsed)) {
    diagnostics.error(locator.at(syntax->offset), "", syntax->message,
                      "a JSON object (RFC 8259, UTF-8, no comments)");
    return std::nullopt;
  }
  return std::move(std::get<LocatedJson>(parsed));
}

std::optional<std::string> LocatedJsonReader::read_name(const json& root) {
  const std::string rule(kMaterialNameRule);
  if (!root.contains("name")) {
    missing("", "name", rule);
    return std::nullopt;
  }
  const json& name = root["name"];
  if (!name.is_string()) {
    error("/name", fmt::format("is {}", describe_type(name)), rule);
    return std::nullopt;
  }
  if (auto problem = material_name_problem(name.get<std::string>())) {
    error("/name", *problem, rule);
    return std::nullopt;
  }
  return name.get<std::string>();
}

SourceLocation LocatedJsonReader::at_value(const std::string& pointer) const {
  return locator_.at(document_.value_offset(pointer));
}

SourceLocation LocatedJsonReader::at_key(const std::string& pointer) const {
  return locator_.at(document_.key_or_value_offset(pointer));
}

void LocatedJsonReader::error(const std::string& pointer, std::string message,
                              std::string allowed) {
  diagnostics_.error(at_value(pointer), field_path(pointer), std::move(message),
                     std::move(allowed));
}

void LocatedJsonReader::missing(const std::string& parent, std::string_view key,
                                std::string allowed) {
  diagnostics_.error(at_value(parent), field_path(child(parent, key)), "is missing",
                     std::move(allowed));
}

std::string LocatedJsonReader::where(std::size_t offset) const {
  const SourceLocation location = locator_.at(offset);
  return fmt::format("{}:{}", location.line, location.column);
}

void LocatedJsonReader::report_duplicate_keys() {
  for (const DuplicateKey& duplicate : document_.duplicates) {
    diagnostics_.error(locator_.at(duplicate.offset), field_path(duplicate.pointer),
                       fmt::format("is given twice (first at {})", where(duplicate.first_offset)),
                       "each field at most once");
  }
}

void LocatedJsonReader::warn_unknown_fields(const json& object, const std::string& pointer,
                                            std::span<const std::string_view> known) {
  for (const auto& [key, value] : object.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    const auto suggestion = closest_match(key, known);
    diagnostics_.warning(
        at_key(child(pointer, key)), field_path(child(pointer, key)),
        suggestion ? fmt::format("unknown field, ignored (did you mean '{}'?)", *suggestion)
                   : "unknown field, ignored",
        fmt::format("known fields here: {}", join(known)));
  }
}

std::optional<double> LocatedJsonReader::read_number(const json& value, const std::string& pointer,
                                                     const Range& range) {
  const std::string allowed = fmt::format("a number in {}", range.describe());
  if (!value.is_number()) {
    error(pointer, fmt::format("is {}", describe_type(value)), allowed);
    return std::nullopt;
  }
  const double number = value.get<double>();
  if (!std::isfinite(number)) {
    error(pointer, "is too large to be represented", allowed);
    return std::nullopt;
  }
  if (!range.contains(number)) {
    error(pointer, fmt::format("{} is out of range", number), allowed);
    return std::nullopt;
  }
  return number;
}

std::optional<runtime::Rgb> LocatedJsonReader::read_rgb(const json& value,
                                                        const std::string& pointer,
                                                        const Range& range) {
  if (value.is_number()) {
    const auto grey = read_number(value, pointer, range);
    if (!grey) return std::nullopt;
    return runtime::Rgb{*grey, *grey, *grey};
  }
  const std::string allowed = fmt::format(
      "a number in {} (grey) or an array of 3 such numbers (R, G, B)", range.describe());
  if (!value.is_array()) {
    error(pointer, fmt::format("is {}", describe_type(value)), allowed);
    return std::nullopt;
  }
  if (value.size() != 3) {
    error(pointer, fmt::format("has {} elements", value.size()), allowed);
    return std::nullopt;
  }
  runtime::Rgb rgb{};
  bool ok = true;
  for (std::size_t c = 0; c < 3; ++c) {
    const auto component = read_number(value[c], pointer + "/" + std::to_string(c), range);
    ok = ok && component.has_value();
    if (component) rgb[c] = *component;
  }
  if (!ok) return std::nullopt;
  return rgb;
}

std::optional<runtime::Rgb> LocatedJsonReader::read_rgb_field(const json& object,
                                                              const std::string& pointer,
                                                              std::string_view key,
                                                              const Range& range) {
  if (!object.contains(key)) {
    missing(pointer, key,
            fmt::format("a number in {} or an array of 3 such numbers", range.describe()));
    return std::nullopt;
  }
  return read_rgb(object[std::string(key)], child(pointer, key), range);
}

const json* LocatedJsonReader::object_field(const json& root, std::string_view key,
                                            std::span<const std::string_view> fields) {
  const json& value = root[std::string(key)];
  const std::string pointer = child("", key);
  if (!value.is_object()) {
    error(pointer, fmt::format("is {}", describe_type(value)),
          fmt::format("an object with the fields {}", join(fields)));
    return nullptr;
  }
  warn_unknown_fields(value, pointer, fields);
  return &value;
}

}  // namespace matc
