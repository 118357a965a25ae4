// Reading a located JSON document field by field with file:line:col diagnostics: the shared base
// of the material file reader and the bake asset reader (numbers with ranges, colours, objects,
// unknown and repeated fields).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "base/diagnostics.h"
#include "matc/runtime/fresnel.h"
#include "material/located_json.h"

namespace matc {

// A closed or half-open interval with the wording used in diagnostics.
struct Range {
  double min;
  double max;
  bool max_inclusive = true;

  bool contains(double value) const {
    return value >= min && (max_inclusive ? value <= max : value < max);
  }
  std::string describe() const;
};

// "a string", "an array", ... for "is <type>" diagnostics.
std::string describe_type(const nlohmann::json& value);

// The JSON pointer of `key` inside the object at `pointer`.
std::string child(const std::string& pointer, std::string_view key);

// `text` as located JSON, or nullopt with its syntax error reported at its line and column.
std::optional<LocatedJson> parse_located_json_reporting(std::string_view text,
                                                        const TextLocator& locator,
                                                        Diagnostics& diagnostics);

class LocatedJsonReader {
 public:
  LocatedJsonReader(const LocatedJson& document, const TextLocator& locator,
                    Diagnostics& diagnostics)
      : document_(document), locator_(locator), diagnostics_(diagnostics) {}

 protected:
  SourceLocation at_value(const std::string& pointer) const;
  SourceLocation at_key(const std::string& pointer) const;
  void error(const std::string& pointer, std::string message, std::string allowed);
  void missing(const std::string& parent, std::string_view key, std::string allowed);
  // "line:col" of a byte offset, for messages that point at a second place.
  std::string where(std::size_t offset) const;
  void report_duplicate_keys();
  void warn_unknown_fields(const nlohmann::json& object, const std::string& pointer,
                           std::span<const std::string_view> known);
  std::optional<double> read_number(const nlohmann::json& value, const std::string& pointer,
                                    const Range& range);
  // A number (grey) or an array of three (R, G, B).
  std::optional<runtime::Rgb> read_rgb(const nlohmann::json& value, const std::string& pointer,
                                       const Range& range);
  // Reads `key` of `object` at `pointer`; reports it missing if absent.
  std::optional<runtime::Rgb> read_rgb_field(const nlohmann::json& object,
                                             const std::string& pointer, std::string_view key,
                                             const Range& range);
  // The root's "name": present, a string, and a valid material name (kMaterialNameRule).
  std::optional<std::string> read_name(const nlohmann::json& root);
  // The object at `key` of the root, or reports that it is not one.
  const nlohmann::json* object_field(const nlohmann::json& root, std::string_view key,
                                     std::span<const std::string_view> fields);

  const LocatedJson& document_;
  const TextLocator& locator_;
  Diagnostics& diagnostics_;
};

}  // namespace matc
