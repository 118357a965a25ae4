#include "matc/emit/material_snippet.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "matc/material/parse.h"
#include "matc/version.h"

namespace matc {

TemplateValues material_template_values(const CompiledMaterial& compiled,
                                        std::string_view inputs_hash) {
  const std::string& name = compiled.material.name;
  // Parsing already validated the name; checked again because it becomes shader identifiers.
  if (const auto problem = material_name_problem(name))
    throw std::logic_error(
        fmt::format("material name '{}' reached the emitter: {}", name, *problem));
  const auto& c = compiled.coefficients;
  const double worst = *std::max_element(compiled.accuracy.decomposition.max_abs.begin(),
                                         compiled.accuracy.decomposition.max_abs.end());
  return {
      {"name", name},
      {"version", kVersion},
      {"version_number", std::to_string(kVersionNumber)},
      {"source_file", comment_safe_file_name(compiled.material.source_path)},
      {"inputs_hash", std::string(inputs_hash)},
      {"f0", fmt::format("{:.4f}, {:.4f}, {:.4f}", compiled.f0[0], compiled.f0[1], compiled.f0[2])},
      {"max_error", fmt::format("{:.4f}", worst)},
      {"color_space", std::string(color_space_name(compiled.color.working_space))},
      {"red", float_list(c[0])},
      {"green", float_list(c[1])},
      {"blue", float_list(c[2])},
      {"red_c", fmt::format("{{{}}}", float_list(c[0], true))},
      {"green_c", fmt::format("{{{}}}", float_list(c[1], true))},
      {"blue_c", fmt::format("{{{}}}", float_list(c[2], true))}};
}

std::string material_snippet_source(ShaderLanguage language, const CompiledMaterial& compiled,
                                    std::string_view inputs_hash) {
  TemplateValues values = material_template_values(compiled, inputs_hash);
  values.erase("red_c");
  values.erase("green_c");
  values.erase("blue_c");
  // A curve matc proved non-negative needs no clamp at 0 (fit/nonnegative_curve.h).
  const bool nonnegative = compiled.fresnel_nonnegative;
  values["fresnel"] = nonnegative ? "matc_fresnel_sum" : "matc_fresnel";
  values["fresnel_preintegrated"] =
      nonnegative ? "matc_fresnel_preintegrated_sum" : "matc_fresnel_preintegrated";
  values["clamp_note"] = nonnegative ? "Its curve stays above 0 (checked when compiled): no clamp."
                                     : "Clamped at 0, where the fitted curve may dip below it.";
  return fill_template(template_path(language, "material"), values);
}

}  // namespace matc
