// A material's generated identifiers are its name after a kind: matc_fresnel_gold,
// matc_fresnel_preintegrated_gold, matc_coefficients_gold, ... Two kinds of name would define one
// identifier twice in a shader that includes the shared library and every material (WGSL has no
// overloads; GLSL refuses a second body): the names below, whose identifiers the shared library or
// the validation kernels already define, and two names one infix apart ('steel' and
// 'preintegrated_steel'). Here, below the material reader and the batch that refuse them; the
// templates are checked against both lists (GeneratedIdentifiers.* in tests/unit/emit).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace matc {

struct NameTakenByLibrary {
  std::string_view name;        // a material name
  std::string_view identifier;  // one identifier of the library that name would define again
};

inline constexpr std::array<NameTakenByLibrary, 13> kNamesTakenByLibrary = {{
    {"f82", "matc_fresnel_f82"},
    {"following", "matc_ltc_quad_light_following"},
    {"following_f82", "matc_ltc_quad_light_following_f82"},
    {"from_baked", "matc_coefficients_from_baked"},
    {"from_f0", "matc_coefficients_from_f0"},
    {"from_f0_entries", "matc_coefficients_from_f0_entries"},
    {"from_f0_table", "matc_coefficients_from_f0_table"},
    {"from_table", "matc_coefficients_from_table"},
    {"from_table_texture", "matc_coefficients_from_table_texture"},
    {"preintegrated", "matc_fresnel_preintegrated"},
    {"preintegrated_sum", "matc_fresnel_preintegrated_sum"},
    {"sum", "matc_fresnel_sum"},
    {"sum_f82", "matc_fresnel_sum_f82"},
}};

// The library identifier a material of this name would define again, or empty.
inline std::string_view identifier_taken_by_library(std::string_view name) {
  for (const NameTakenByLibrary& taken : kNamesTakenByLibrary)
    if (taken.name == name) return taken.identifier;
  return {};
}

// Kinds that extend another kind (matc_fresnel_ + "preintegrated_" = matc_fresnel_preintegrated_):
// a name and the same name after one of these define the same identifier.
inline constexpr std::array<std::string_view, 3> kIdentifierInfixes = {
    "preintegrated_", "preintegrated_textured_", "textured_"};

// Every name whose identifiers meet `name`'s (its infixed and de-infixed forms), each paired with
// an identifier both would define.
struct IdentifierNeighbour {
  std::string name;
  std::string identifier;
};
inline std::vector<IdentifierNeighbour> identifier_neighbours(std::string_view name) {
  std::vector<IdentifierNeighbour> neighbours;
  for (const std::string_view infix : kIdentifierInfixes) {
    std::string longer = std::string(infix) + std::string(name);
    neighbours.push_back({longer, "matc_fresnel_" + longer});
    if (name.size() > infix.size() && name.starts_with(infix))
      neighbours.push_back(
          {std::string(name.substr(infix.size())), "matc_fresnel_" + std::string(name)});
  }
  return neighbours;
}

}  // namespace matc
