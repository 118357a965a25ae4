#include "matc/emit/shader_library.h"

#include <array>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "matc/emit/template.h"
#include "matc/runtime/analytic_lut.h"
#include "matc/version.h"

namespace matc {
namespace {

// One vector literal per line, comma-separated, indented for the array initialiser.
std::string vector_rows(ShaderLanguage language, std::span<const double> values,
                        std::size_t width) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); i += width) {
    out.append("    ");
    out.append(vector_literal(language, values.subspan(i, width)));
    out.append(i + width < values.size() ? ",\n" : "");
  }
  return out;
}

std::string embedded_lut_source(ShaderLanguage language, const Lut& lut) {
  const std::vector<double> texels(lut.texels.begin(), lut.texels.end());
  return fill_template(
      template_path(language, "embedded_lut"),
      {{"embedded_size", std::to_string(lut.size)},
       {"embedded_texels", std::to_string(lut.size * lut.size)},
       {"embedded_texel_values", vector_rows(language, texels, runtime::kBasisSize)}});
}

// How a mutable vec3 of the basis' values is declared.
std::string_view vector_declaration(ShaderLanguage language) {
  switch (language) {
    case ShaderLanguage::hlsl:
      return "float3";
    case ShaderLanguage::wgsl:
      return "var";
    case ShaderLanguage::glsl:
      break;
  }
  return "vec3";
}

// Horner's rule for b_1..b_3, unrolled, each coefficient selected by segment
// (matc_basis_coefficient in the templates, written for four segments).
std::string horner_steps(ShaderLanguage language, const runtime::BasisPolynomial& polynomial) {
  static_assert(runtime::kPolynomialSegments == 4, "matc_basis_coefficient selects among four");
  std::string out;
  for (std::size_t power = 0; power <= runtime::kPolynomialDegree; ++power) {
    out.append(power == 0 ? fmt::format("  {} b = ", vector_declaration(language))
                          : "  b = b * t + ");
    out.append("matc_basis_coefficient(segment,");
    for (std::size_t segment = 0; segment < runtime::kPolynomialSegments; ++segment) {
      out.append(segment % 2 == 0 ? "\n      " : " ");
      out.append(vector_literal(language, polynomial[segment][power]));
      out.append(segment + 1 < runtime::kPolynomialSegments ? "," : ");");
    }
    if (power < runtime::kPolynomialDegree) out.append("\n");
  }
  return out;
}

// matc_basis(): the fitted bases' piecewise polynomial, or the powers basis' closed form.
std::string basis_function_source(ShaderLanguage language, const runtime::ShaderBasis& basis) {
  if (basis.form == runtime::ShaderBasisForm::powers) {
    return fill_template(template_path(language, "basis_powers"), {});
  }
  return fill_template(template_path(language, "basis_polynomial"),
                       {{"segments", std::to_string(runtime::kPolynomialSegments)},
                        {"last_segment", std::to_string(runtime::kPolynomialSegments - 1)},
                        {"degree", std::to_string(runtime::kPolynomialDegree)},
                        {"horner_steps", horner_steps(language, basis.polynomial)}});
}

// The closed form's 36 matrix constants (4 channels x 3x3 blocks) and the four channel calls.
// GLSL and WGSL take matrices by column, HLSL by row: either way block (A, B) maps the powers
// y^(4B..4B+3) to the rows p = 4A..4A+3.
std::string analytic_lut_source(ShaderLanguage language, runtime::BasisKind basis) {
  const runtime::AnalyticLutCoefficients& coefficients = runtime::shipped_analytic_lut(basis);
  constexpr std::size_t kBlocks = runtime::kAnalyticLutTerms / 4;
  static_assert(kBlocks == 3, "the templates' matc_analytic_lut_channel takes 3x3 blocks");
  std::string constants;
  std::string channels;
  for (std::size_t c = 0; c < runtime::kBasisSize; ++c) {
    channels += fmt::format("{}\n      matc_analytic_lut_channel(x0, x1, x2, y0, y1, y2",
                            c == 0 ? "" : ",");
    for (std::size_t a = 0; a < kBlocks; ++a) {
      for (std::size_t b = 0; b < kBlocks; ++b) {
        const std::string name = fmt::format("MATC_ANALYTIC_LUT_{}_{}{}", c, a, b);
        channels += fmt::format(",{}{}", b == 0 ? "\n          " : " ", name);  // a row a line
        std::string values;
        for (std::size_t outer = 0; outer < 4; ++outer) {
          for (std::size_t inner = 0; inner < 4; ++inner) {
            // Column-major (GLSL, WGSL): outer is the column q; row-major (HLSL): the row p.
            const bool by_row = language == ShaderLanguage::hlsl;
            const std::size_t p = 4 * a + (by_row ? outer : inner);
            const std::size_t q = 4 * b + (by_row ? inner : outer);
            values += fmt::format("{}{}", values.empty() ? "" : ", ",
                                  float_literal(coefficients[c][p][q]));
          }
        }
        switch (language) {
          case ShaderLanguage::glsl:
            constants += fmt::format("const mat4 {} = mat4({});\n", name, values);
            break;
          case ShaderLanguage::hlsl:
            constants += fmt::format("static const float4x4 {} = float4x4({});\n", name, values);
            break;
          case ShaderLanguage::wgsl:
            constants += fmt::format("const {} = mat4x4f({});\n", name, values);
            break;
        }
      }
    }
    channels += ")";
  }
  return fill_template(template_path(language, "analytic_lut"),
                       {{"basis", std::string(runtime::basis_name(basis))},
                        {"analytic_lut_constants", constants},
                        {"analytic_lut_channels", channels}});
}

std::string area_light_source(ShaderLanguage language, std::size_t ltc_size) {
  constexpr double kSides = static_cast<double>(runtime::kDiskLightSides);
  const double step = 2.0 * std::numbers::pi / kSides;
  return fill_template(
      template_path(language, "area_lights"),
      {{"ltc_size", std::to_string(ltc_size)},
       {"disk_sides", std::to_string(runtime::kDiskLightSides)},
       {"disk_angle_step", float_literal(step)},
       {"disk_circumradius_scale",
        float_literal(std::sqrt(2.0 * std::numbers::pi / (kSides * std::sin(step))))}});
}

}  // namespace

std::string shader_library_source(ShaderLanguage language, const runtime::ShaderBasis& basis,
                                  const ShaderLibraryOptions& options,
                                  std::string_view inputs_hash) {
  return fill_template(
      template_path(language, "matc_fresnel"),
      {{"version", kVersion},
       {"version_number", std::to_string(kVersionNumber)},
       {"inputs_hash", std::string(inputs_hash)},
       {"lut_size", std::to_string(options.lut_size)},
       {"basis_function", basis_function_source(language, basis)},
       {"coefficient_table",
        options.coefficient_table_functions
            ? fill_template(
                  template_path(language, "coefficient_table"),
                  {{"coefficient_table_size", std::to_string(options.coefficient_table_size)}}) +
                  fill_template(template_path(language, "baked_coefficients"), {})
            : ""},
       {"area_lights",
        options.area_light_functions ? area_light_source(language, options.ltc_size) : ""},
       {"analytic_lut",
        options.analytic_lut ? analytic_lut_source(language, *options.analytic_lut) : ""},
       {"embedded_lut",
        options.embedded_lut ? embedded_lut_source(language, *options.embedded_lut) : ""}});
}

}  // namespace matc
