#include "material_renderer.h"

#include <optional>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "emit/fullscreen_shaders.h"
#include "lut/film_table_files.h"
#include "matc/runtime/film_table.h"
#include "matc/runtime/ltc.h"
#include "matc/vulkan/fullscreen_pass.h"
#include "material/material_input.h"
#include "material/parse.h"
#include "optics/coat.h"

namespace matc::render {
namespace {

constexpr std::size_t kCurveSize = 1024;

// The exact curves at kCurveSize cosines, RGBA: the material's curve in rgb; for a coated one the
// metal under the coat in rgb and the coat's Fresnel in a, then the metal in air in rgb
// (coated_render.frag layers them).
std::vector<float> exact_curve(const CompiledMaterial& compiled) {
  const auto in_air = make_reflectance_curve(compiled.material, compiled.color);
  std::vector<float> curve(2 * kCurveSize * 4, 0.0f);
  const auto write = [&](const ReflectanceCurve& source, std::size_t first, std::size_t channels) {
    for (std::size_t j = 0; j < kCurveSize; ++j) {
      const Rgb value = source.at(static_cast<double>(j) / (kCurveSize - 1));
      for (std::size_t c = 0; c < channels; ++c)
        curve[4 * (first + j) + c] = static_cast<float>(value[c]);
    }
  };
  if (!compiled.coat) {
    write(*in_air, 0, 3);
    return curve;
  }
  write(*make_under_coat_curve(compiled.material, compiled.color.working_space), 0, 3);
  const CoatCurve coat(compiled.coat->input.ior);
  for (std::size_t j = 0; j < kCurveSize; ++j)
    curve[4 * j + 3] = static_cast<float>(coat.at(static_cast<double>(j) / (kCurveSize - 1))[0]);
  write(*in_air, kCurveSize, 3);
  return curve;
}

}  // namespace

MaterialRenderer::MaterialRenderer(const RenderSettings& settings, const BuildOptions& options,
                                   MaterialRenderSource source, std::string fragment_name,
                                   bool with_ltc, EstimateMethods methods)
    : settings_(settings),
      source_(source),
      fragment_name_(std::move(fragment_name)),
      methods_(methods),
      build_(options),
      context_(vulkan::ContextOptions{settings.validation, settings.device}),
      lobes_(runtime::shipped_basis().samples()),
      lobe_lut_(preintegrate_lut(lobes_.view(), {})),
      table_size_(static_cast<std::uint32_t>(build_.stored_lut().size)),
      ours_table_(context_, table_size_, table_size_, build_.stored_lut().texels),
      lobe_table_(context_, table_size_, table_size_, lobe_lut_.texels),
      sampler_(context_),
      curve_(context_, 2 * kCurveSize * 4 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      vertex_(compile_fullscreen_stage(fullscreen_vertex_source(), ShaderStage::vertex,
                                       "fullscreen.vert")) {
  if (with_ltc) {
    const runtime::LtcTableView ltc = runtime::shipped_ltc_table();
    ltc_table_.emplace(context_, static_cast<std::uint32_t>(ltc.size),
                       static_cast<std::uint32_t>(ltc.size), ltc.texels);
  }
}

std::optional<CompiledMaterial> MaterialRenderer::compile(const std::string& file) const {
  const ParseResult parsed = read_material_file(file);
  for (const Diagnostic& diagnostic : parsed.diagnostics.items())
    fmt::print(stderr, "{}\n", format_diagnostic(diagnostic));
  if (!parsed.material) return std::nullopt;
  return compile_material(*parsed.material, build_.basis());
}

std::optional<std::vector<CompiledMaterial>> MaterialRenderer::compile_all(
    const std::string& file) const {
  const MaterialInput input = read_material_input(file);
  for (const Diagnostic& diagnostic : input.diagnostics.items())
    fmt::print(stderr, "{}\n", format_diagnostic(diagnostic));
  if (input.diagnostics.has_errors()) return std::nullopt;
  std::vector<CompiledMaterial> compiled;
  for (const Material& material : input.materials)
    compiled.push_back(compile_material(material, build_.basis()));
  return compiled;
}

bool MaterialRenderer::draws(const std::string& file, const CompiledMaterial& compiled, bool coated,
                             bool filmed) {
  // A filmed metal's functions read its own table (docs/thin-film.md), which only matc_render
  // and matc_area_light_render bind.
  if (compiled.film_table && !filmed) {
    fmt::print(stderr,
               "{}: error: {} has a film: its shaders read its own table, which only matc_render "
               "and matc_area_light_render draw (docs/thin-film.md)\n",
               file, compiled.material.name);
    return false;
  }
  if (compiled.coat.has_value() == coated) return true;
  if (coated) {
    fmt::print(stderr,
               "{}: error: {} has no coat: matc_coated_render draws coated metals, matc_render "
               "bare ones\n",
               file, compiled.material.name);
  } else {
    fmt::print(stderr,
               "{}: error: {} is coated: this render draws bare metals; matc_coated_render draws "
               "coated ones\n",
               file, compiled.material.name);
  }
  return false;
}

std::vector<Panel> MaterialRenderer::render(const CompiledMaterial& compiled) {
  curve_.write<float>(exact_curve(compiled));
  const SpirvWords fragment = compile_fullscreen_stage(
      source_(build_, compiled, kCurveSize, settings_.size, settings_.size), ShaderStage::fragment,
      fragment_name_);
  std::vector<vulkan::Binding> bindings = {vulkan::Binding::sampled_image(0, ours_table_),
                                           vulkan::Binding::sampled_image(1, lobe_table_),
                                           vulkan::Binding::separate_sampler(2, sampler_),
                                           vulkan::Binding::storage_buffer(3, curve_)};
  if (ltc_table_) bindings.push_back(vulkan::Binding::sampled_image(4, *ltc_table_));
  // A filmed metal's own table, as its file stores it (the comparison render reads it at 4, the
  // area-light render at 5, after its LTC table).
  std::optional<vulkan::Image> film;
  if (compiled.film_table) {
    film.emplace(context_, static_cast<std::uint32_t>(runtime::FilmTable::kWidth),
                 static_cast<std::uint32_t>(runtime::FilmTable::kHeight),
                 stored_film_texels(*compiled.film_table, build_.options().lut_precision));
    bindings.push_back(vulkan::Binding::sampled_image(ltc_table_ ? 5 : 4, *film));
  }
  vulkan::FullscreenPass pass(context_, vertex_, fragment, bindings, settings_.size, settings_.size,
                              sizeof(PanelConstants));
  const auto roughness =
      static_cast<float>(compiled.material.roughness.value_or(kDefaultRoughness));
  return render_estimates(pass, settings_.size, settings_.samples, roughness, methods_);
}

}  // namespace matc::render
