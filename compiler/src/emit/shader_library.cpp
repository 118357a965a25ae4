#include "matc/emit/shader_library.h"

#include <array>

#include <fmt/format.h>

#include "matc/emit/template.h"
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
      language == ShaderLanguage::glsl ? "glsl/embedded_lut.glsl" : "hlsl/embedded_lut.hlsl",
      {{"embedded_size", std::to_string(lut.size)},
       {"embedded_texels", std::to_string(lut.size * lut.size)},
       {"embedded_texel_values", vector_rows(language, texels, runtime::kBasisSize)}});
}

std::string horner_steps() {
  std::string out;
  for (std::size_t power = 1; power <= runtime::kPolynomialDegree; ++power) {
    out.append(fmt::format("  b = b * t + MATC_BASIS_POLYNOMIAL[first + {}];", power));
    if (power < runtime::kPolynomialDegree) out.append("\n");
  }
  return out;
}

}  // namespace

std::string shader_library_source(ShaderLanguage language,
                                  const runtime::BasisPolynomial& polynomial,
                                  const ShaderLibraryOptions& options,
                                  std::string_view inputs_hash) {
  constexpr std::size_t kTerms = runtime::kPolynomialDegree + 1;
  std::vector<double> coefficients;
  for (const runtime::PolynomialSegment& segment : polynomial) {
    for (const std::array<double, 3>& triple : segment)
      coefficients.insert(coefficients.end(), triple.begin(), triple.end());
  }
  return fill_template(
      language == ShaderLanguage::glsl ? "glsl/matc_fresnel.glsl" : "hlsl/matc_fresnel.hlsl",
      {{"version", kVersion},
       {"version_number", std::to_string(kVersionNumber)},
       {"inputs_hash", std::string(inputs_hash)},
       {"lut_size", std::to_string(options.lut_size)},
       {"segments", std::to_string(runtime::kPolynomialSegments)},
       {"last_segment", std::to_string(runtime::kPolynomialSegments - 1)},
       {"degree", std::to_string(runtime::kPolynomialDegree)},
       {"terms_per_segment", std::to_string(kTerms)},
       {"horner_steps", horner_steps()},
       {"polynomial_terms", std::to_string(runtime::kPolynomialSegments * kTerms)},
       {"basis_polynomial", vector_rows(language, coefficients, 3)},
       {"embedded_lut",
        options.embedded_lut ? embedded_lut_source(language, *options.embedded_lut) : ""}});
}

}  // namespace matc
