// The JSON layout matc writes: objects one member per line, arrays of scalars on one line
// (an [r, g, b] triple stays readable), two-space indent, trailing newline. Numbers use
// nlohmann's shortest round-trip form, so the same values always give the same bytes.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace matc {

std::string format_json(const nlohmann::ordered_json& value);

}  // namespace matc
