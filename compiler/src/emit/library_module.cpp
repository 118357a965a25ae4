#include "emit/library_module.h"

#include <cstdint>

#include <fmt/format.h>

#include "spirv/linkage.h"
#include "spirv/spirv_tools.h"

namespace matc {

SpirvWords compile_library_module(std::string glsl_source, const std::string& name,
                                  std::span<const std::string> exports) {
  glsl_source.insert(0, "#version 450\n");
  glsl_source.append("\nvoid main() {}\n");
  const SpirvWords compiled = compile_to_spirv({ShaderLanguage::glsl, std::move(glsl_source), name,
                                                "main", /*keep_uncalled_functions=*/true});
  const SpirvWords library = export_functions(compiled, exports);
  validate_spirv(library, SpirvTarget::universal_1_3, name);
  return optimize_spirv(library, SpirvTarget::universal_1_3, name);
}

std::string spirv_file_bytes(const SpirvWords& words) {
  std::string bytes(words.size() * sizeof(std::uint32_t), '\0');
  for (std::size_t i = 0; i < words.size(); ++i) {
    for (std::size_t b = 0; b < 4; ++b)  // SPIR-V files are little-endian words
      bytes[4 * i + b] = static_cast<char>((words[i] >> (8 * b)) & 0xffu);
  }
  return bytes;
}

std::vector<std::string> shared_library_exports(
    bool embedded_lut, std::span<const std::string> further_layer_suffixes) {
  std::vector<std::string> names = {"matc_basis",
                                    "matc_fresnel",
                                    "matc_lut_texcoord",
                                    "matc_fresnel_preintegrated",
                                    "matc_energy_compensation",
                                    "matc_preintegrated_basis_analytic",
                                    "matc_coefficient_table_texcoord",
                                    "matc_channel_coefficients",
                                    "matc_coefficients_from_table",
                                    "matc_artistic_from_ior",
                                    "matc_coefficients_from_baked",
                                    "matc_coefficients_from_f0",
                                    "matc_ltc_texcoord",
                                    "matc_ltc_transform",
                                    "matc_ltc_quad_integral",
                                    "matc_ltc_disk_integral",
                                    "matc_ltc_sphere_integral",
                                    "matc_ltc_quad_light",
                                    "matc_ltc_disk_light",
                                    "matc_ltc_sphere_light",
                                    "matc_ltc_quad_light_following",
                                    "matc_ltc_disk_light_following",
                                    "matc_ltc_sphere_light_following"};
  if (embedded_lut) names.emplace_back("matc_preintegrated_basis_embedded");
  // What templates/<language>/basis_layer.* defines again per further layer.
  for (const std::string& suffix : further_layer_suffixes) {
    for (const std::string_view layer_function :
         {"matc_basis", "matc_fresnel", "matc_lut_texcoord", "matc_preintegrated_basis_analytic",
          "matc_ltc_quad_light_following", "matc_ltc_disk_light_following",
          "matc_ltc_sphere_light_following"}) {
      names.push_back(fmt::format("{}{}", layer_function, suffix));
    }
    if (embedded_lut) names.push_back("matc_preintegrated_basis_embedded" + suffix);
  }
  return names;
}

std::vector<std::string> material_library_exports(std::string_view material_name, bool coated) {
  std::vector<std::string> names = {fmt::format("matc_fresnel_{}", material_name),
                                    fmt::format("matc_fresnel_preintegrated_{}", material_name)};
  if (coated) {
    names.push_back(fmt::format("matc_coat_fresnel_{}", material_name));
    names.push_back(fmt::format("matc_coat_fresnel_preintegrated_{}", material_name));
  }
  return names;
}

}  // namespace matc
