#include "base/json_format.h"

#include <algorithm>

namespace matc {
namespace {

using nlohmann::ordered_json;

bool is_flat(const ordered_json& array) {
  return std::none_of(array.begin(), array.end(),
                      [](const ordered_json& element) { return element.is_structured(); });
}

void write(const ordered_json& value, std::size_t depth, std::string& out) {
  const std::string indent((depth + 1) * 2, ' ');
  const std::string closing_indent(depth * 2, ' ');
  if (value.is_object() && !value.empty()) {
    out += "{\n";
    bool first = true;
    for (const auto& [key, member] : value.items()) {
      if (!first) out += ",\n";
      first = false;
      out += indent + ordered_json(key).dump() + ": ";
      write(member, depth + 1, out);
    }
    out += "\n" + closing_indent + "}";
  } else if (value.is_array() && !value.empty() && !is_flat(value)) {
    out += "[\n";
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (i > 0) out += ",\n";
      out += indent;
      write(value[i], depth + 1, out);
    }
    out += "\n" + closing_indent + "]";
  } else if (value.is_array()) {
    out += "[";
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (i > 0) out += ", ";
      out += value[i].dump();
    }
    out += "]";
  } else {
    out += value.dump();
  }
}

}  // namespace

std::string format_json(const nlohmann::ordered_json& value) {
  std::string out;
  write(value, 0, out);
  out += "\n";
  return out;
}

std::string format_json_nested(const nlohmann::ordered_json& value, std::size_t depth) {
  std::string out;
  write(value, depth, out);
  return out;
}

}  // namespace matc
