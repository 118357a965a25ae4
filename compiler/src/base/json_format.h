// The JSON layout matc writes: objects one member per line, arrays of scalars on one line
// (an [r, g, b] triple stays readable), two-space indent, trailing newline. Numbers use
// nlohmann's shortest round-trip form, so the same values always give the same bytes.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace matc {

std::string format_json(const nlohmann::ordered_json& value);
// The same layout for a value nested `depth` levels deep, without the trailing newline: what
// format_json writes for it inside a larger document (used to assemble large documents from
// parts formatted one at a time).
std::string format_json_nested(const nlohmann::ordered_json& value, std::size_t depth);

}  // namespace matc
