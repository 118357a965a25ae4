// Area-light renders on a Vulkan device (lavapipe by default): a sphere on a plane under a
// two-sided rectangular light (templates/glsl/area_light_render.frag), four ways:
//   Monte-Carlo reference with the exact Fresnel | LTC x Schlick's | LTC x ours |
//   LTC x the exact preintegrated Fresnel (LTC's own error alone).
// Writes <name>_area.png (the four panels), <name>_area_difference.png (Schlick's and ours
// against the reference, 4x) and <name>_area_fresnel_difference.png (against LTC with the exact
// Fresnel: the Fresnel's share alone), and prints the error table of docs/rendering.md.
//   matc_area_light_render [--size N] [--samples N] [-o DIR] [--check] FILES...
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "matc/compile.h"
#include "matc/emit/build.h"
#include "matc/emit/fullscreen_shaders.h"
#include "matc/lut/comparison_lobes.h"
#include "matc/material/parse.h"
#include "matc/runtime/ltc.h"
#include "matc/vulkan/buffer.h"
#include "matc/vulkan/fullscreen_pass.h"
#include "matc/vulkan/sampler.h"
#include "panels.h"

namespace {

using namespace matc::render;

constexpr std::size_t kCurveSize = 1024;

// The estimates of area_light_render.frag by method number (the Estimate slots they occupy).
constexpr Estimate kLtcExact = kExactFbar;
constexpr Estimate kExactLobeSplit = kPrefilteredRadiance;
constexpr Estimate kLtcSchlick = kSchlickFbar;
constexpr Estimate kLtcOurs = kOursFbar;

class AreaLightRenderer {
 public:
  explicit AreaLightRenderer(const RenderSettings& settings)
      : settings_(settings),
        build_(matc::BuildOptions{}),
        context_(matc::vulkan::ContextOptions{settings.validation, settings.device}),
        lobes_(matc::runtime::shipped_basis().samples()),
        lobe_lut_(matc::preintegrate_lut(lobes_.view(), {})),
        table_size_(static_cast<std::uint32_t>(build_.stored_lut().size)),
        ours_table_(context_, table_size_, table_size_, build_.stored_lut().texels),
        lobe_table_(context_, table_size_, table_size_, lobe_lut_.texels),
        ltc_table_(context_, static_cast<std::uint32_t>(matc::runtime::shipped_ltc_table().size),
                   static_cast<std::uint32_t>(matc::runtime::shipped_ltc_table().size),
                   matc::runtime::shipped_ltc_table().texels),
        sampler_(context_),
        curve_(context_, kCurveSize * 4 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
        vertex_(matc::compile_fullscreen_stage(matc::fullscreen_vertex_source(),
                                               matc::ShaderStage::vertex, "fullscreen.vert")) {}

  const matc::vulkan::Context& context() const { return context_; }
  matc::runtime::BasisView basis() const { return build_.basis(); }

  std::array<Panel, kEstimateCount> render(const matc::CompiledMaterial& compiled) {
    const auto exact = matc::make_reflectance_curve(compiled.material);
    std::vector<float> curve(kCurveSize * 4, 0.0f);
    for (std::size_t j = 0; j < kCurveSize; ++j) {
      const matc::Rgb value = exact->at(static_cast<double>(j) / (kCurveSize - 1));
      for (std::size_t c = 0; c < 3; ++c)
        curve[4 * j + c] = static_cast<float>(value[c]);
    }
    curve_.write<float>(curve);
    const matc::SpirvWords fragment = matc::compile_fullscreen_stage(
        matc::area_light_render_source(build_, compiled, kCurveSize, settings_.size,
                                       settings_.size),
        matc::ShaderStage::fragment, "area_light_render.frag");
    const std::array bindings = {matc::vulkan::Binding::sampled_image(0, ours_table_),
                                 matc::vulkan::Binding::sampled_image(1, lobe_table_),
                                 matc::vulkan::Binding::separate_sampler(2, sampler_),
                                 matc::vulkan::Binding::storage_buffer(3, curve_),
                                 matc::vulkan::Binding::sampled_image(4, ltc_table_)};
    matc::vulkan::FullscreenPass pass(context_, vertex_, fragment, bindings, settings_.size,
                                      settings_.size, sizeof(PanelConstants));
    const float roughness =
        static_cast<float>(compiled.material.roughness.value_or(kDefaultRoughness));
    return render_estimates(pass, settings_.size, settings_.samples, roughness);
  }

 private:
  RenderSettings settings_;
  matc::Build build_;
  matc::vulkan::Context context_;
  matc::ComparisonLobes lobes_;
  matc::Lut lobe_lut_;
  std::uint32_t table_size_;
  matc::vulkan::Image ours_table_;
  matc::vulkan::Image lobe_table_;
  matc::vulkan::Image ltc_table_;
  matc::vulkan::LutSampler sampler_;
  matc::vulkan::Buffer curve_;
  matc::SpirvWords vertex_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Area-light renders: Monte-Carlo reference, LTC with Schlick's Fresnel, with ours"};
  RenderSettings settings;
  settings.output = "render-out";
  std::vector<std::string> files;
  app.add_option("files", files, "Material files (.json)")->required();
  add_render_options(app, settings,
                     "Exit 1 unless, for every material, LTC with ours is no further from the "
                     "reference than LTC with Schlick's and its Fresnel error is at most a tenth "
                     "of Schlick's");
  CLI11_PARSE(app, argc, argv);

  try {
    AreaLightRenderer renderer(settings);
    std::filesystem::create_directories(settings.output);
    fmt::print(
        "Rendered on {}, {}x{} pixels per panel, {} samples per pixel. Mean and max absolute "
        "error in linear radiance over the sphere's and the plane's pixels and all channels, "
        "against the Monte-Carlo reference with the exact Fresnel (relative: mean error / mean "
        "reference radiance) and against LTC with the exact preintegrated Fresnel (the "
        "Fresnel's share alone):\n\n"
        "| material | roughness | LTC with | mean | relative | max | Fresnel alone: mean | "
        "Fresnel alone: max |\n|---|---:|---|---:|---:|---:|---:|---:|\n",
        renderer.context().device_name(), settings.size, settings.size, settings.samples);
    bool targets_met = true;
    for (const std::string& file : files) {
      const matc::ParseResult parsed = matc::read_material_file(file);
      for (const matc::Diagnostic& diagnostic : parsed.diagnostics.items())
        fmt::print(stderr, "{}\n", matc::format_diagnostic(diagnostic));
      if (!parsed.material) return 1;
      const matc::CompiledMaterial compiled =
          matc::compile_material(*parsed.material, renderer.basis());
      const std::array<Panel, kEstimateCount> estimates = renderer.render(compiled);
      const Panel& reference = estimates[kReference];
      const Panel& schlick = estimates[kLtcSchlick];
      const Panel& ours = estimates[kLtcOurs];
      const Panel& exact = estimates[kLtcExact];
      const Panel& split = estimates[kExactLobeSplit];
      const std::string name = compiled.material.name + "_area";
      write_panels(settings.output / (name + ".png"),
                   {reference.rgb, schlick.rgb, ours.rgb, exact.rgb}, settings.size, display);
      write_panels(settings.output / (name + "_difference.png"),
                   {difference(schlick, reference), difference(ours, reference)}, settings.size,
                   display_difference);
      write_panels(settings.output / (name + "_fresnel_difference.png"),
                   {difference(schlick, exact), difference(ours, exact)}, settings.size,
                   display_difference);
      const double roughness = compiled.material.roughness.value_or(kDefaultRoughness);
      const std::array<std::pair<const char*, const Panel*>, 4> rows = {
          std::pair{"Schlick's Fresnel", &schlick}, std::pair{"ours", &ours},
          std::pair{"the exact preintegrated Fresnel", &exact},
          std::pair{"(no LTC: the exact lobe, the exact preintegrated Fresnel)", &split}};
      for (const auto& [label, panel] : rows) {
        const ErrorStats total = error_against(*panel, reference);
        const ErrorStats fresnel = error_against(*panel, exact);
        fmt::print("| {} | {:.3f} | {} | {:.4f} | {:.1f}% | {:.3f} | {} | {} |\n",
                   compiled.material.name, roughness, label, total.mean,
                   100.0 * total.relative_mean, total.max,
                   panel == &exact || panel == &split ? "-" : fmt::format("{:.4f}", fresnel.mean),
                   panel == &exact || panel == &split ? "-" : fmt::format("{:.3f}", fresnel.max));
      }
      targets_met = targets_met &&
                    error_against(ours, reference).mean <= error_against(schlick, reference).mean &&
                    error_against(ours, exact).mean <= 0.1 * error_against(schlick, exact).mean;
    }
    if (!validation_clean(renderer.context())) return 1;
    if (settings.check && !targets_met) {
      fmt::print(stderr,
                 "matc_area_light_render: LTC with ours misses a target (no further from the "
                 "reference than Schlick's, a tenth of its Fresnel error)\n");
      return 1;
    }
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc_area_light_render: error: {}\n", error.what());
    return 1;
  }
  return 0;
}
