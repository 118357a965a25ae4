#include "pipeline/unique_names.h"

#include <fmt/core.h>

#include "material/parse.h"

namespace matc {

bool UniqueNames::claim(const Material& material, std::string_view scope,
                        Diagnostics& diagnostics) {
  return claim(material.name, material.source_path, material.name_location, scope, diagnostics);
}

bool UniqueNames::claim(const std::string& name, const std::string& path,
                        const SourceLocation& location, std::string_view scope,
                        Diagnostics& diagnostics) {
  const auto [first, inserted] = first_use_.try_emplace(
      material_name_key(name), FirstUse{path, location.line, location.column});
  if (inserted) return true;
  diagnostics.error(
      location, "name",
      fmt::format("'{}' is already used by {} ({}:{})", name, first->second.path,
                  first->second.line, first->second.column),
      fmt::format("names unique within {}, ignoring case (they name output files)", scope));
  return false;
}

}  // namespace matc
