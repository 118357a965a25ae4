#include "emit/c_header.h"

#include <fmt/format.h>

#include "emit/material_snippet.h"

namespace matc {
namespace {

// A coated material's coat (docs/coating.md), after its in-air coefficients; nothing for a bare
// metal, whose header stays as it was.
std::string coat_block(const CompiledMaterial& compiled) {
  if (!compiled.coat) return "";
  const runtime::CoatCoefficients& c = compiled.coat->coefficients;
  return fmt::format(
      "\n\n/* Under a coat (docs/coating.md): the metal seen through it (its curve at the "
      "metal/coat\n * interface, at the cosines inside the coat), the coat's dielectric Fresnel, "
      "and the coat's\n * weight, perceptual roughness, index and round-trip tint; "
      "{}.spv also exports\n * matc_coat_fresnel_{} and matc_coat_fresnel_preintegrated_{}. */\n"
      "static const MatcFresnelCoefficients matc_under_coat_coefficients_{} = {{\n"
      "    {{{}}},\n    {{{}}},\n    {{{}}}}};\n"
      "static const float matc_coat_coefficients_{}[4] = {{{}}};\n"
      "#define MATC_{}_COAT_WEIGHT {}\n#define MATC_{}_COAT_ROUGHNESS {}\n"
      "#define MATC_{}_COAT_IOR {}\n"
      "static const float matc_coat_color_{}[3] = {{{}}};",
      compiled.material.name, compiled.material.name, compiled.material.name,
      compiled.material.name, float_list(c.under_coat[0], true), float_list(c.under_coat[1], true),
      float_list(c.under_coat[2], true), compiled.material.name, float_list(c.coat, true),
      compiled.material.name, c_float_literal(c.weight), compiled.material.name,
      c_float_literal(c.roughness), compiled.material.name, c_float_literal(c.ior),
      compiled.material.name, float_list(c.color, true));
}

}  // namespace

std::string material_c_header(const CompiledMaterial& compiled, std::string_view inputs_hash,
                              const LutReference& lut, const SpirvWords& library_module,
                              std::optional<std::size_t> lut_layer) {
  TemplateValues values = material_template_values(compiled, inputs_hash);
  values.erase("red");
  values.erase("green");
  values.erase("blue");
  values.erase("version_number");
  std::string words;
  for (std::size_t i = 0; i < library_module.size(); ++i) {
    words.append(i % 8 == 0 ? "    " : " ");
    words.append(fmt::format("0x{:08x}u,", library_module[i]));
    if (i % 8 == 7 && i + 1 < library_module.size()) words.append("\n");
  }
  values.insert({{"lut_file", lut.file},
                 {"lut_size", std::to_string(lut.size)},
                 {"lut_hash", lut.hash},
                 {"basis", std::string(runtime::basis_name(compiled.basis))},
                 {"lut_layer",
                  lut_layer ? fmt::format("\n/* Its layer of the table, the basis' (matc --basis "
                                          "auto): columns [layer size, (layer + 1) size). */\n"
                                          "#define MATC_{}_LUT_LAYER {}",
                                          compiled.material.name, *lut_layer)
                            : ""},
                 {"spirv_word_count", std::to_string(library_module.size())},
                 {"spirv_words", words},
                 {"coat_block", coat_block(compiled)}});
  return fill_template("c/material.h", values);
}

}  // namespace matc
