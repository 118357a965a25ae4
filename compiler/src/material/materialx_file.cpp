// The parts of MaterialX reading that need no XML parser: names, extensions, reading the file.
#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "matc/material/materialx_import.h"

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
  return out;  // no "__": runs of '_' were folded, and leading ones dropped
}

bool is_materialx_path(std::string_view path) {
  if (path.size() < 5) return false;
  std::string extension(path.substr(path.size() - 5));
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".mtlx";
}

MaterialXImport read_materialx_file(const std::string& path, const FileLoader& loader) {
  const LoadedFile loaded = loader(path, kMaxMaterialXFileBytes);
  if (!loaded.bytes) {
    MaterialXImport result;
    result.diagnostics.error({path, 0, 0}, "", fmt::format("cannot read: {}", loaded.error),
                             "a MaterialX document of at most 16 MiB");
    return result;
  }
  return import_materialx(*loaded.bytes, path);
}

}  // namespace matc
