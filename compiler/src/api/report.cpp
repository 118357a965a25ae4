#include "matc/api/report.h"

#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "checked_options.h"
#include "compile/compile.h"
#include "pipeline/unique_names.h"
#include "public_diagnostics.h"
#include "report/fresnel_plot.h"
#include "report/material_curves.h"
#include "report/report_page.h"

namespace matc::api {

Report report(std::span<const Material> materials, const CompileOptions& options) {
  const BasisChoice choice = basis_choice_of(options);
  const ColorOptions color = color_options_of(options);
  Diagnostics names_used;
  UniqueNames names;
  for (const Material& material : materials)
    names.claim(material.value(), "a report", names_used);
  throw_if_errors(names_used);

  Report out;
  Diagnostics fits;
  std::vector<ReportEntry> entries;
  for (const Material& material : materials) {
    const matc::Material& value = material.value();
    const runtime::BasisKind kind = chosen_basis(value, choice);
    const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(kind);
    const matc::CompiledMaterial compiled =
        compile_material(value, runtime::shipped_basis(kind), color);
    warn_if_poor_fit(compiled, fits);
    const MaterialCurves curves = sample_material_curves(compiled, shader_basis);
    const std::string source = std::filesystem::path(value.source_path).filename().string();
    // A coated material's whole surface, as its curves are (docs/coating.md); a filmed metal's
    // shaders read its table, not the 4-term fit (docs/thin-film.md).
    FitAccuracy accuracy = compiled.coat ? compiled.coat->layered_accuracy : compiled.accuracy;
    if (compiled.film_table && !compiled.coat) accuracy.decomposition = compiled.film_table_error;
    const std::string subtitle = fmt::format(
        "{}, basis {}{}: worst-channel max error ours {:.4f}, Schlick {:.4f}, F82-tint {:.4f}",
        source, runtime::basis_name(kind), compiled.coat ? ", coated" : "",
        worst_channel(accuracy.decomposition.max_abs), worst_channel(accuracy.schlick.max_abs),
        worst_channel(accuracy.f82_tint.max_abs));
    out.files.push_back({value.name + ".svg", fresnel_plot_svg(curves, value.name, subtitle)});
    out.files.push_back({value.name + ".csv", material_curves_csv(curves)});
    entries.push_back(
        {value.name, source, compiled.coat ? compiled.coat->layered_f0 : compiled.f0, accuracy});
  }
  out.files.push_back({"index.html", report_index_html(entries, option_name(choice))});
  out.diagnostics = public_diagnostics(fits);
  return out;
}

}  // namespace matc::api
