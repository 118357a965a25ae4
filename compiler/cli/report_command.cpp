// `matc report FILES... -o DIR`: per material an SVG plot and a CSV of its curves, and an HTML
// index with the error tables. All inputs are checked first; with any invalid, nothing is written.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "color_options.h"
#include "commands.h"
#include "lut_options.h"
#include "matc/api/files.h"
#include "matc/compile/compile.h"
#include "matc/material/material_input.h"
#include "matc/pipeline/unique_names.h"
#include "matc/report/fresnel_plot.h"
#include "matc/report/material_curves.h"
#include "matc/report/report_page.h"
#include "print_diagnostics.h"

namespace matc::cli {
namespace {

struct ReportOptions {
  std::vector<std::string> files;
  std::string output_directory = "matc-report";
  runtime::BasisKind basis = runtime::kDefaultBasis;
  ColorOptions color;
};

namespace fs = std::filesystem;

// Every material, or none when any file is invalid or two names would share an output file.
std::optional<std::vector<Material>> read_all(const std::vector<std::string>& files) {
  std::vector<Material> materials;
  UniqueNames names;
  bool ok = true;
  for (const std::string& file : files) {
    MaterialInput input = read_material_input(file);
    for (Material& material : input.materials) {
      names.claim(material, "a report", input.diagnostics);
      materials.push_back(std::move(material));
    }
    print_diagnostics(input.diagnostics);
    if (input.diagnostics.has_errors() || input.materials.empty()) ok = false;
  }
  if (!ok) return std::nullopt;
  return materials;
}

int run_report(const ReportOptions& options) {
  const std::optional<std::vector<Material>> materials = read_all(options.files);
  if (!materials) {
    fmt::print(stderr, "matc report: nothing written: fix the inputs above\n");
    return kExitInputError;
  }
  const runtime::BasisKind kind = options.basis;
  const runtime::BasisView basis = runtime::shipped_basis(kind);
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(kind);

  struct Output {
    std::string name;
    std::string bytes;
  };
  std::vector<Output> outputs;
  std::vector<ReportEntry> entries;
  for (const Material& material : *materials) {
    const CompiledMaterial compiled = compile_material(material, basis, options.color);
    Diagnostics fit;
    warn_if_poor_fit(compiled, fit);
    print_diagnostics(fit);
    const MaterialCurves curves = sample_material_curves(compiled, shader_basis);
    const std::string source = fs::path(material.source_path).filename().string();
    // A coated material's whole surface, as its curves are (docs/coating.md).
    const FitAccuracy& accuracy =
        compiled.coat ? compiled.coat->layered_accuracy : compiled.accuracy;
    const std::string subtitle = fmt::format(
        "{}, basis {}{}: worst-channel max error ours {:.4f}, Schlick {:.4f}, F82-tint {:.4f}",
        source, runtime::basis_name(kind), compiled.coat ? ", coated" : "",
        worst_channel(accuracy.decomposition.max_abs), worst_channel(accuracy.schlick.max_abs),
        worst_channel(accuracy.f82_tint.max_abs));
    outputs.push_back({material.name + ".svg", fresnel_plot_svg(curves, material.name, subtitle)});
    outputs.push_back({material.name + ".csv", material_curves_csv(curves)});
    entries.push_back(
        {material.name, source, compiled.coat ? compiled.coat->layered_f0 : compiled.f0, accuracy});
  }
  outputs.push_back({"index.html", report_index_html(entries, runtime::basis_name(kind))});

  const fs::path directory(options.output_directory);
  fs::create_directories(directory);
  std::size_t written = 0;
  for (const Output& output : outputs) {
    if (api::write_file((directory / output.name).string(), output.bytes) ==
        api::WriteOutcome::written)
      ++written;
  }
  fmt::print(stderr, "matc report: {} materials, {} files written, {} unchanged: {}\n",
             materials->size(), written, outputs.size() - written,
             (directory / "index.html").string());
  return kExitSuccess;
}

}  // namespace

Command register_report(CLI::App& app) {
  auto options = std::make_shared<ReportOptions>();
  CLI::App* command = app.add_subcommand(
      "report",
      "Plot each material's Fresnel curves (exact, ours, Schlick, F82-tint) as SVG, with CSV "
      "samples and an HTML index of the errors");
  command->add_option("files", options->files, "Material files (.json), MaterialX documents")
      ->required();
  command->add_option("-o,--output", options->output_directory, "Output directory")
      ->capture_default_str();
  add_basis_option(*command, options->basis);
  add_color_options(*command, options->color);

  return {command, [options] { return run_report(*options); }, true};
}

}  // namespace matc::cli
