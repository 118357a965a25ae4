#include "emit/c_header.h"

#include <fmt/format.h>

#include "emit/material_snippet.h"
#include "lut/film_table_files.h"

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

// A filmed metal's table (runtime/film_table.h), which its functions read instead of the
// coefficients; nothing for a metal without a film.
std::string film_block(const CompiledMaterial& compiled, LutPrecision precision) {
  if (!compiled.film_table) return "";
  const std::vector<float> texels = compiled.film_stack
                                        ? stored_film_texels(*compiled.film_stack, precision)
                                        : stored_film_texels(*compiled.film_table, precision);
  const std::size_t height = texels.size() / (4 * runtime::FilmTable::kWidth);
  std::string rows;
  for (std::size_t i = 0; i < texels.size(); ++i) {
    rows.append(i % 8 == 0 ? "    " : " ");
    rows.append(c_float_literal(texels[i]) + ",");
    if (i % 8 == 7 && i + 1 < texels.size()) rows.append("\n");
  }
  return fmt::format(
      "\n\n/* Under a thin film (docs/thin-film.md): F and Fbar come from the film's own table, "
      "the texels\n * of {0}.film.<ext> ({1} x {2} RGBA, row after row; upload it as that "
      "texture). The\n * coefficients above are the 4-term fit's, for F0.{5} */\n"
      "#define MATC_{0}_FILM_TABLE_WIDTH {1}\n#define MATC_{0}_FILM_TABLE_HEIGHT {2}\n{6}"
      "static const float matc_film_table_{0}[{3}] = {{\n{4}}};",
      compiled.material.name, runtime::FilmTable::kWidth, height, texels.size(), rows,
      compiled.coat ? " Under the coat the table holds\n * the base lobe, the coat's "
                      "transmission and tint included: the coat lobe is the coat's own."
      : compiled.film_stack
          ? fmt::format(" A thickness per pixel: {} slices of films from\n * {} to {} nm "
                        "(docs/thin-film.md).",
                        compiled.film_stack->slices.size(), compiled.film_stack->minimum_nm,
                        compiled.film_stack->maximum_nm)
          : "",
      compiled.film_stack ? fmt::format("#define MATC_{}_FILM_SLICES {}\n", compiled.material.name,
                                        compiled.film_stack->slices.size())
                          : "");
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
                 {"coat_block", coat_block(compiled)},
                 {"film_block", film_block(compiled, lut.precision)}});
  return fill_template("c/material.h", values);
}

}  // namespace matc
