// The parts of MaterialX reading that need no XML parser: names and extensions.
#include <cctype>

#include "base/identifier_names.h"
#include "material/materialx_import.h"

namespace matc {

std::string sanitized_material_name(std::string_view name) {
  std::string out;
  for (const char c : name) {
    const bool keep =
        std::isalnum(static_cast<unsigned char>(c)) != 0 && static_cast<unsigned char>(c) < 0x80;
    const char next = keep ? c : '_';
    if (next == '_' && (out.empty() || out.back() == '_')) continue;
    out += next;
  }
  if (out.empty()) return "material";
  if (!std::isalpha(static_cast<unsigned char>(out.front()))) out = "m_" + out;
  if (out.size() > kMaxMaterialNameLength) out.resize(kMaxMaterialNameLength);
  if (!identifier_taken_by_library(out).empty()) out += "_material";  // those names are short
  return out;  // no "__": runs of '_' were folded, and leading ones dropped
}

bool is_materialx_path(std::string_view path) {
  return path_has_extension(path, ".mtlx");
}

}  // namespace matc
