// Filling the shader and header templates under templates/ (embedded at build time).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace matc {

using TemplateValues = std::map<std::string, std::string, std::less<>>;

// `text` with every {{key}} replaced by values[key]. A placeholder without a value, or a value no
// placeholder uses, is a bug in matc: std::logic_error naming `template_name`.
std::string fill_template_text(std::string_view text, const TemplateValues& values,
                               std::string_view template_name);

// The same for the embedded template at `path` relative to templates/, e.g. "glsl/material.glsl".
std::string fill_template(std::string_view path, const TemplateValues& values);

}  // namespace matc
