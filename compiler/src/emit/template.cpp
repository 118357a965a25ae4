#include "emit/template.h"

#include <set>
#include <stdexcept>

#include <fmt/core.h>

#include "base/embedded_templates.h"

namespace matc {

std::string fill_template_text(std::string_view text, const TemplateValues& values,
                               std::string_view template_name) {
  std::string out;
  out.reserve(text.size());
  std::set<std::string_view> used;
  std::size_t position = 0;
  while (true) {
    const std::size_t open = text.find("{{", position);
    if (open == std::string_view::npos) break;
    const std::size_t close = text.find("}}", open + 2);
    if (close == std::string_view::npos)
      throw std::logic_error(fmt::format("template {}: unclosed '{{{{'", template_name));
    const std::string_view key = text.substr(open + 2, close - open - 2);
    const auto value = values.find(key);
    if (value == values.end())
      throw std::logic_error(
          fmt::format("template {}: no value for {{{{{}}}}}", template_name, key));
    out.append(text.substr(position, open - position));
    out.append(value->second);
    used.insert(value->first);
    position = close + 2;
  }
  out.append(text.substr(position));
  for (const auto& [key, value] : values) {
    if (!used.contains(key))
      throw std::logic_error(
          fmt::format("template {}: {{{{{}}}}} is never used", template_name, key));
  }
  return out;
}

std::string fill_template(std::string_view path, const TemplateValues& values) {
  return fill_template_text(embedded_templates::file(path), values, path);
}

}  // namespace matc
