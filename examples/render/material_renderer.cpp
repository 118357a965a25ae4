#include "material_renderer.h"

#include <utility>
#include <vector>

#include <fmt/core.h>

#include "matc/emit/fullscreen_shaders.h"
#include "matc/material/parse.h"
#include "matc/runtime/ltc.h"
#include "matc/vulkan/fullscreen_pass.h"

namespace matc::render {
namespace {

constexpr std::size_t kCurveSize = 1024;

}  // namespace

MaterialRenderer::MaterialRenderer(const RenderSettings& settings, const BuildOptions& options,
                                   MaterialRenderSource source, std::string fragment_name,
                                   bool with_ltc)
    : settings_(settings),
      source_(source),
      fragment_name_(std::move(fragment_name)),
      build_(options),
      context_(vulkan::ContextOptions{settings.validation, settings.device}),
      lobes_(runtime::shipped_basis().samples()),
      lobe_lut_(preintegrate_lut(lobes_.view(), {})),
      table_size_(static_cast<std::uint32_t>(build_.stored_lut().size)),
      ours_table_(context_, table_size_, table_size_, build_.stored_lut().texels),
      lobe_table_(context_, table_size_, table_size_, lobe_lut_.texels),
      sampler_(context_),
      curve_(context_, kCurveSize * 4 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
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

std::array<Panel, kEstimateCount> MaterialRenderer::render(const CompiledMaterial& compiled) {
  const auto exact = make_reflectance_curve(compiled.material, compiled.color);
  std::vector<float> curve(kCurveSize * 4, 0.0f);
  for (std::size_t j = 0; j < kCurveSize; ++j) {
    const Rgb value = exact->at(static_cast<double>(j) / (kCurveSize - 1));
    for (std::size_t c = 0; c < 3; ++c)
      curve[4 * j + c] = static_cast<float>(value[c]);
  }
  curve_.write<float>(curve);
  const SpirvWords fragment = compile_fullscreen_stage(
      source_(build_, compiled, kCurveSize, settings_.size, settings_.size), ShaderStage::fragment,
      fragment_name_);
  std::vector<vulkan::Binding> bindings = {vulkan::Binding::sampled_image(0, ours_table_),
                                           vulkan::Binding::sampled_image(1, lobe_table_),
                                           vulkan::Binding::separate_sampler(2, sampler_),
                                           vulkan::Binding::storage_buffer(3, curve_)};
  if (ltc_table_) bindings.push_back(vulkan::Binding::sampled_image(4, *ltc_table_));
  vulkan::FullscreenPass pass(context_, vertex_, fragment, bindings, settings_.size, settings_.size,
                              sizeof(PanelConstants));
  const auto roughness =
      static_cast<float>(compiled.material.roughness.value_or(kDefaultRoughness));
  return render_estimates(pass, settings_.size, settings_.samples, roughness);
}

}  // namespace matc::render
