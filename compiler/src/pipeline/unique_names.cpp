#include "pipeline/unique_names.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "base/identifier_names.h"
#include "material/parse.h"

namespace matc {

bool UniqueNames::claim(const Material& material, std::string_view scope,
                        Diagnostics& diagnostics) {
  return claim(material.name, material.source_path, material.name_location, scope, diagnostics);
}

bool UniqueNames::claim(const std::string& name, const std::string& path,
                        const SourceLocation& location, std::string_view scope,
                        Diagnostics& diagnostics) {
  const std::string key = material_name_key(name);
  // 'steel' and 'preintegrated_steel' would both define matc_fresnel_preintegrated_steel
  // (identifiers keep case: 'Preintegrated_steel' would not).
  for (const IdentifierNeighbour& neighbour : identifier_neighbours(name)) {
    const auto other = first_use_.find(material_name_key(neighbour.name));
    if (other == first_use_.end() || other->second.name != neighbour.name) continue;
    diagnostics.error(
        location, "name",
        fmt::format("'{}' and the material of {} ({}:{}) would both define {}", name,
                    other->second.path, other->second.line, other->second.column,
                    neighbour.identifier),
        fmt::format("no two names within {} that differ only by a '{}' in front (it is part "
                    "of the generated names)",
                    scope, fmt::join(kIdentifierInfixes, "', '")));
    return false;
  }
  const auto [first, inserted] =
      first_use_.try_emplace(key, FirstUse{name, path, location.line, location.column});
  if (inserted) return true;
  diagnostics.error(
      location, "name",
      fmt::format("'{}' is already used by {} ({}:{})", name, first->second.path,
                  first->second.line, first->second.column),
      fmt::format("names unique within {}, ignoring case (they name output files)", scope));
  return false;
}

}  // namespace matc
