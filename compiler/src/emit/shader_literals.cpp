#include "emit/shader_literals.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

namespace matc {

std::string shader_file_extension(ShaderLanguage language) {
  return fmt::format(".{}", shader_language_name(language));
}

std::string template_path(ShaderLanguage language, std::string_view stem) {
  return fmt::format("{0}/{1}.{0}", shader_language_name(language), stem);
}

std::string float_literal(double value) {
  const auto single = static_cast<float>(value);
  if (!std::isfinite(single)) throw std::logic_error("a non-finite number cannot be emitted");
  // fmt prints the shortest digits that read back to the same float.
  std::string text = fmt::format("{}", single == 0.0f ? 0.0f : single);
  if (text.find_first_of(".e") == std::string::npos) text.append(".0");
  return text;
}

std::string c_float_literal(double value) {
  std::string text = float_literal(value);
  text.push_back('f');
  return text;
}

std::string float_list(std::span<const double> values, bool c_suffix) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out.append(", ");
    out.append(c_suffix ? c_float_literal(values[i]) : float_literal(values[i]));
  }
  return out;
}

std::string vector_literal(ShaderLanguage language, std::span<const double> values) {
  switch (language) {
    case ShaderLanguage::hlsl:
      return fmt::format("float{}({})", values.size(), float_list(values));
    case ShaderLanguage::wgsl:
      return fmt::format("vec{}f({})", values.size(), float_list(values));
    case ShaderLanguage::glsl:
      break;
  }
  return fmt::format("vec{}({})", values.size(), float_list(values));
}

std::string comment_safe_file_name(std::string_view path) {
  std::string name = std::filesystem::path(path).filename().string();
  for (char& c : name) {
    const bool safe = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '_' || c == '-';
    if (!safe) c = '_';
  }
  return name;
}

}  // namespace matc
