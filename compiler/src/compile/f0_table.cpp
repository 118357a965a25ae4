#include "compile/f0_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

#include "fit/accuracy.h"
#include "fit/coefficients.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/shader_basis.h"

namespace matc {

bool has_f0_table(const Material& material, const ColorOptions& color) {
  return std::holds_alternative<F82TintInput>(material.model) &&
         color.gamut_mapping == GamutMapping::none &&
         input_color_space(material, color.working_space) == color.working_space;
}

runtime::F0Table compile_f0_table(const Material& material, const runtime::BasisView& basis,
                                  const ColorOptions& color) {
  if (!has_f0_table(material, color))
    throw std::logic_error("an F0 table needs an F82-tint material whose channels stay apart");
  runtime::F0Table table;
  if (material.coat) table.under_coat.emplace();
  Material entry = material;
  for (std::size_t i = 0; i < runtime::kF0TableEntries; ++i) {
    const double f0 = runtime::f0_table_entry_f0(i);
    std::get<F82TintInput>(entry.model).f0 = {f0, f0, f0};
    // As compile_material solves: on the accuracy grid's cosines, which it evaluates once.
    const auto in_air = make_working_space_curve(entry, color.working_space);
    table.in_air[i] = solve_coefficients(AccuracyGridCurve(*in_air), basis);
    if (table.under_coat) {
      const auto under = make_under_coat_curve(entry, color.working_space);
      (*table.under_coat)[i] = solve_coefficients(AccuracyGridCurve(*under), basis);
    }
  }
  return table;
}

namespace {

// F at mu of in-air coefficients and, for a coated metal, its coat: what the shaders sum.
Rgb shaded(const runtime::Coefficients& in_air, const runtime::CoatCoefficients* coat,
           const runtime::ShaderBasis& basis, double mu) {
  return coat ? runtime::evaluate_coated_fresnel(in_air, *coat, basis, mu).total()
              : runtime::evaluate_fresnel(in_air, basis, mu);
}

double largest(const Rgb& values) {
  return *std::max_element(values.begin(), values.end());
}

}  // namespace

F0TableError measure_f0_table(const Material& material, const runtime::BasisView& basis,
                              const ColorOptions& color, std::span<const double> f0s) {
  const runtime::ShaderBasis& shader = runtime::shipped_shader_basis(basis.kind);
  const runtime::F0Table table = compile_f0_table(material, basis, color);
  F0TableError out;
  Material at_f0 = material;
  for (const double f0 : f0s) {
    std::get<F82TintInput>(at_f0.model).f0 = {f0, f0, f0};
    const CompiledMaterial compiled = compile_material(at_f0, basis, color);
    out.fit = std::max(out.fit, largest(compiled.coat ? compiled.coat->layered_error.max_abs
                                                      : compiled.accuracy.decomposition.max_abs));
    const runtime::Coefficients in_air = runtime::coefficients_from_f0_table(table, {f0, f0, f0});
    std::optional<runtime::CoatCoefficients> coat;
    if (compiled.coat) {
      coat = compiled.coat->coefficients;
      coat->under_coat = runtime::under_coat_coefficients_from_f0_table(table, {f0, f0, f0});
    }
    const runtime::CoatCoefficients* compiled_coat =
        compiled.coat ? &compiled.coat->coefficients : nullptr;
    for (int j = 0; j <= 256; ++j) {
      const double mu = j / 256.0;
      const Rgb ours = shaded(in_air, coat ? &*coat : nullptr, shader, mu);
      const Rgb reference = shaded(compiled.coefficients, compiled_coat, shader, mu);
      for (std::size_t c = 0; c < 3; ++c)
        out.table = std::max(out.table, std::abs(ours[c] - reference[c]));
    }
  }
  return out;
}

}  // namespace matc
