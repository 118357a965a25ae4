// JSON parsing that remembers where every key and value starts, for file:line:col diagnostics.
// nlohmann::json 3.11 keeps no positions, so its SAX parser is driven over an iterator that counts
// how far the lexer has read; each token's start is recovered by skipping the whitespace and
// separators between the previous event and this one.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

namespace matc {

struct DuplicateKey {
  std::string pointer;           // JSON pointer of the member, e.g. "/artistic/edge_tint"
  std::size_t offset = 0;        // where the repeated key starts
  std::size_t first_offset = 0;  // where the first occurrence starts
};

struct LocatedJson {
  nlohmann::json value;  // on duplicate keys the last occurrence wins; see `duplicates`
  std::unordered_map<std::string, std::size_t> value_offsets;  // JSON pointer -> value start
  std::unordered_map<std::string, std::size_t> key_offsets;    // JSON pointer -> key start
  // JSON pointer of an object or array -> one past its closing bracket (for splicing text).
  std::unordered_map<std::string, std::size_t> container_ends;
  std::vector<DuplicateKey> duplicates;

  std::size_t value_offset(const std::string& pointer) const;
  // The member's key if it has one (object members), else its value.
  std::size_t key_or_value_offset(const std::string& pointer) const;
};

struct JsonSyntaxError {
  std::size_t offset = 0;
  std::string message;  // nlohmann's description without its own position prefix
};

inline constexpr std::size_t kMaxJsonDepth = 64;

std::variant<LocatedJson, JsonSyntaxError> parse_located_json(std::string_view text);

// "/artistic/reflectivity/1" -> "artistic.reflectivity[1]".
std::string field_path(std::string_view pointer);

}  // namespace matc
