#include "emit/shader_library.h"

#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "emit/layer_suffix.h"
#include "emit/template.h"
#include "matc/runtime/analytic_lut.h"
#include "matc/runtime/powers_basis.h"
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

// `suffix` and `of_basis` name a further layer's copy ("_f82", " of the f82 basis"), empty for the
// first basis'.
std::string embedded_lut_source(ShaderLanguage language, const Lut& lut, const std::string& suffix,
                                const std::string& of_basis) {
  const std::vector<double> texels(lut.texels.begin(), lut.texels.end());
  return fill_template(
      template_path(language, "embedded_lut"),
      {{"suffix", suffix},
       {"of_basis", of_basis},
       {"embedded_size", std::to_string(lut.size)},
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

// A closed form's shader steps: matc_basis()'s {variable, expression} lines to b1 = m^a and
// b2 = x m^b (the steps of runtime/powers_basis.h) with their count of multiplies, and how
// matc_fresnel_sum() orders the sum for the fewest operations: powers as
// c_0 + c_2 b_2 + b_1 (c_1 + c_3 b_2); f82, whose b_2 = mu m b_1, as
// c_0 + b_1 (c_1 + mu m (c_2 + c_3 b_1)), which needs b_1 and mu m alone.
struct ClosedFormSteps {
  std::string_view multiplies;
  std::array<std::array<std::string_view, 2>, 4> lines;  // an empty variable ends them
  std::string_view sum_comment;
  bool sum_needs_x_m;  // the sum reads `xm` = mu m
  std::string_view sum;
};

const ClosedFormSteps& closed_form_steps(runtime::BasisKind kind) {
  static constexpr ClosedFormSteps kPowers{
      "Five",
      {{{"m3", "m * m * m"}, {"b1", "m3 * m3"}, {"b2", "x * m3"}, {}}},
      "c_0 + c_2 b_2 + b_1 (c_1 + c_3 b_2)\n// (b_3 = b_2 b_1)",
      false,
      "c0 + c2 * b.z + b.y * (c1 + c3 * b.z)"};
  static constexpr ClosedFormSteps kF82{
      "Six",
      {{{"m2", "m * m"}, {"m4", "m2 * m2"}, {"b1", "m4 * m"}, {"b2", "x * (m4 * m2)"}}},
      "c_0 + b_1 (c_1 + mu m (c_2 + c_3 b_1))\n// (b_2 = mu m b_1, b_3 = b_2 b_1)",
      true,
      "c0 + b.y * (c1 + xm * (c2 + c3 * b.y))"};
  return kind == runtime::BasisKind::f82 ? kF82 : kPowers;
}

// The lines of matc_fresnel_sum() before its coefficients: the basis, and mu m where the sum
// reads it (the optimiser shares the clamp and 1 - x with the inlined matc_basis()).
std::string closed_form_sum_basis(ShaderLanguage language, const ClosedFormSteps& steps,
                                  std::string_view suffix) {
  std::string out;
  switch (language) {
    case ShaderLanguage::glsl:
      out = fmt::format("  vec4 b = matc_basis{}(mu);", suffix);
      if (steps.sum_needs_x_m)
        out += "\n  float x = clamp(mu, 0.0, 1.0);\n  float xm = x * (1.0 - x);";
      break;
    case ShaderLanguage::hlsl:
      out = fmt::format("  float4 b = matc_basis{}(mu);", suffix);
      if (steps.sum_needs_x_m) out += "\n  float x = saturate(mu);\n  float xm = x * (1.0 - x);";
      break;
    case ShaderLanguage::wgsl:
      out = fmt::format("  let b = matc_basis{}(mu);", suffix);
      if (steps.sum_needs_x_m) out += "\n  let x = clamp(mu, 0.0, 1.0);\n  let xm = x * (1.0 - x);";
      break;
  }
  return out;
}

// `suffix` follows every function's name: empty for the first basis of a build, "_f82" for a
// further layer's.
std::string closed_form_basis_source(ShaderLanguage language, runtime::ShaderBasisForm form,
                                     std::string_view suffix) {
  const runtime::BasisKind kind =
      form == runtime::ShaderBasisForm::f82 ? runtime::BasisKind::f82 : runtime::BasisKind::powers;
  const ClosedFormSteps& steps = closed_form_steps(kind);
  const runtime::ClosedFormExponents exponents = runtime::closed_form_exponents(kind);
  const std::string_view declare = language == ShaderLanguage::wgsl ? "let" : "float";
  std::string body;
  for (const auto& [variable, expression] : steps.lines)
    if (!variable.empty()) body += fmt::format("  {} {} = {};\n", declare, variable, expression);
  body.pop_back();  // the template ends the last line
  return fill_template(template_path(language, "basis_powers"),
                       {{"basis", std::string(runtime::basis_name(kind))},
                        {"edge_power", std::to_string(exponents.edge)},
                        {"lobe_power", std::to_string(exponents.lobe)},
                        {"product_power", std::to_string(exponents.edge + exponents.lobe)},
                        {"multiplies", std::string(steps.multiplies)},
                        {"powers", body},
                        {"sum_comment", std::string(steps.sum_comment)},
                        {"sum_basis", closed_form_sum_basis(language, steps, suffix)},
                        {"sum", std::string(steps.sum)},
                        {"suffix", std::string(suffix)}});
}

// matc_basis(): the fitted bases' piecewise polynomial, or a closed form.
std::string basis_function_source(ShaderLanguage language, const runtime::ShaderBasis& basis) {
  if (basis.is_closed_form()) return closed_form_basis_source(language, basis.form, "");
  return fill_template(template_path(language, "basis_polynomial"),
                       {{"segments", std::to_string(runtime::kPolynomialSegments)},
                        {"last_segment", std::to_string(runtime::kPolynomialSegments - 1)},
                        {"degree", std::to_string(runtime::kPolynomialDegree)},
                        {"horner_steps", horner_steps(language, basis.polynomial)}});
}

// The closed form's body: T_0..T_12 of x and y as scalars, then E, mu_a, mu_b and t as sums
// over p of T_p(x) times a sum over q of a_pq T_q(y) (runtime::analytic_lut_polynomial's order),
// each coefficient a literal.
std::string analytic_lut_fields_source(ShaderLanguage language,
                                       const runtime::AnalyticLutCoefficients& coefficients) {
  const std::string declare = language == ShaderLanguage::wgsl ? "let" : "float";
  std::string out;
  for (const char axis : {'x', 'y'}) {
    out += fmt::format("  {0} {1}0 = 1.0;\n  {0} {1}1 = {1};\n", declare, axis);
    for (std::size_t k = 2; k <= runtime::kAnalyticLutAlbedoDegree; ++k)
      out += fmt::format("  {0} {1}{2} = 2.0 * {1} * {1}{3} - {1}{4};\n", declare, axis, k, k - 1,
                         k - 2);
  }
  const auto polynomial = [&](const char* name, std::span<const double> values,
                              std::size_t degree) {
    out += fmt::format("  {} {} =", declare, name);
    std::size_t term = 0;
    for (std::size_t p = 0; p <= degree; ++p) {
      std::string row;
      for (std::size_t q = 0; q + p <= degree; ++q, ++term) {
        row += q == 0 ? float_literal(values[term])
                      : fmt::format(" + {} * y{}", float_literal(values[term]), q);
      }
      out +=
          p == 0 ? fmt::format("\n      ({})", row) : fmt::format(" +\n      x{} * ({})", p, row);
    }
    out += ";\n";
  };
  polynomial("albedo", coefficients.albedo, runtime::kAnalyticLutAlbedoDegree);
  polynomial("node_a", coefficients.node_a, runtime::kAnalyticLutQuadratureDegree);
  polynomial("node_b", coefficients.node_b, runtime::kAnalyticLutQuadratureDegree);
  polynomial("weight_b", coefficients.weight_b, runtime::kAnalyticLutQuadratureDegree);
  out.pop_back();  // the template ends the line
  return out;
}

std::string analytic_lut_source(ShaderLanguage language, runtime::BasisKind basis,
                                std::string_view suffix) {
  std::string constant_suffix(suffix);
  for (char& c : constant_suffix)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return fill_template(
      template_path(language, "analytic_lut"),
      {{"basis", std::string(runtime::basis_name(basis))},
       {"suffix", std::string(suffix)},
       {"constant_suffix", constant_suffix},
       {"analytic_lut_fields",
        analytic_lut_fields_source(language, runtime::shipped_analytic_lut(basis))}});
}

// The area-light functions that evaluate F (the quality level's, whose Fresnel follows the light):
// the first basis' (`suffix` empty) or a further layer's, with `suffix` on their names.
std::string area_light_following_source(ShaderLanguage language, std::string_view suffix,
                                        std::string_view part) {
  return fill_template(template_path(language, part), {{"suffix", std::string(suffix)}});
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
        float_literal(std::sqrt(2.0 * std::numbers::pi / (kSides * std::sin(step))))},
       {"following", area_light_following_source(language, "", "area_lights_following")},
       {"following_lights",
        area_light_following_source(language, "", "area_lights_following_lights")}});
}

// matc_lut_texcoord: over the whole table, or over its first layer of several.
std::string lut_texcoord_source(ShaderLanguage language, const ShaderLibraryOptions& options) {
  if (options.further_layers.empty())
    return fill_template(template_path(language, "lut_texcoord"), {});
  return fill_template(template_path(language, "lut_layers"),
                       {{"lut_layers", std::to_string(1 + options.further_layers.size())}});
}

// Each further layer's functions (templates/<language>/basis_layer.*).
std::string basis_layers_source(ShaderLanguage language, const ShaderLibraryOptions& options) {
  std::string out;
  for (std::size_t k = 0; k < options.further_layers.size(); ++k) {
    const runtime::BasisKind basis = options.further_layers[k];
    const std::string name(runtime::basis_name(basis));
    const std::string suffix = layer_suffix(basis);
    const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(basis);
    if (!shader_basis.is_closed_form())
      throw std::logic_error("a table's further layers are closed forms");
    out += fill_template(
        template_path(language, "basis_layer"),
        {{"basis", name},
         {"layer", std::to_string(k + 1)},
         {"basis_function", closed_form_basis_source(language, shader_basis.form, suffix)},
         {"analytic_lut",
          options.analytic_lut ? "\n" + analytic_lut_source(language, basis, suffix) : ""},
         {"area_light",
          options.area_light_functions
              ? "\n" + area_light_following_source(language, suffix, "area_lights_following") +
                    "\n" +
                    area_light_following_source(language, suffix, "area_lights_following_lights")
              : ""},
         {"embedded_lut", options.embedded_luts.empty()
                              ? ""
                              : embedded_lut_source(language, options.embedded_luts[k + 1], suffix,
                                                    " of the " + name + " basis")}});
  }
  return out;
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
       {"lut_texcoord", lut_texcoord_source(language, options)},
       {"basis_layers", basis_layers_source(language, options)},
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
        options.analytic_lut ? analytic_lut_source(language, *options.analytic_lut, "") : ""},
       {"embedded_lut",
        options.embedded_luts.empty()
            ? ""
            : embedded_lut_source(language, options.embedded_luts.front(), "", "")}});
}

}  // namespace matc
