// Comparison renders on a Vulkan device (lavapipe by default): a sphere under a procedural sky,
// image-based lighting three ways (templates/glsl/comparison_render.frag):
//   Monte-Carlo reference with the exact Fresnel | Schlick's split sum | ours.
// Writes <name>.png (the three panels), <name>_difference.png (|Schlick - reference| and
// |ours - reference|, 4x) and prints the error table of docs/rendering.md. A third split sum,
// with the exact preintegrated Fresnel, separates the split sum's own error from the Fresnel's:
// <name>_fresnel_difference.png shows Schlick's and ours against it.
//   matc_render [--size N] [--samples N] [-o DIR] [--check] FILES...
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "matc/compile.h"
#include "matc/emit/build.h"
#include "matc/emit/fullscreen_shaders.h"
#include "matc/lut/comparison_lobes.h"
#include "matc/lut/split_sum_reference.h"
#include "matc/material/parse.h"
#include "matc/vulkan/buffer.h"
#include "matc/vulkan/fullscreen_pass.h"
#include "matc/vulkan/sampler.h"
#include "panels.h"

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kCurveSize = 1024;
using namespace matc::render;

struct ComparisonSettings : RenderSettings {
  std::string basis{matc::runtime::basis_name(matc::runtime::kDefaultBasis)};
};

matc::BuildOptions build_options(const ComparisonSettings& settings) {
  matc::BuildOptions options;
  options.basis = *matc::runtime::basis_from_name(settings.basis);
  return options;
}

class Renderer {
 public:
  explicit Renderer(const ComparisonSettings& settings)
      : settings_(settings),
        build_(build_options(settings)),
        context_(matc::vulkan::ContextOptions{settings.validation, settings.device}),
        lobes_(matc::runtime::shipped_basis().samples()),
        lobe_lut_(matc::preintegrate_lut(lobes_.view(), {})),
        table_size_(static_cast<std::uint32_t>(build_.stored_lut().size)),
        ours_table_(context_, table_size_, table_size_, build_.stored_lut().texels),
        lobe_table_(context_, table_size_, table_size_, lobe_lut_.texels),
        sampler_(context_),
        curve_(context_, kCurveSize * 4 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
        vertex_(matc::compile_fullscreen_stage(matc::fullscreen_vertex_source(),
                                               matc::ShaderStage::vertex, "fullscreen.vert")) {}

  const matc::vulkan::Context& context() const { return context_; }
  matc::runtime::BasisView basis() const { return build_.basis(); }

  // Every estimate of one material, linear RGB, indexed by Estimate.
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
        matc::comparison_render_source(build_, compiled, kCurveSize, settings_.size,
                                       settings_.size),
        matc::ShaderStage::fragment, "comparison_render.frag");
    const std::array bindings = {matc::vulkan::Binding::sampled_image(0, ours_table_),
                                 matc::vulkan::Binding::sampled_image(1, lobe_table_),
                                 matc::vulkan::Binding::separate_sampler(2, sampler_),
                                 matc::vulkan::Binding::storage_buffer(3, curve_)};
    matc::vulkan::FullscreenPass pass(context_, vertex_, fragment, bindings, settings_.size,
                                      settings_.size, sizeof(PanelConstants));
    const float roughness =
        static_cast<float>(compiled.material.roughness.value_or(kDefaultRoughness));
    return render_estimates(pass, settings_.size, settings_.samples, roughness);
  }

 private:
  ComparisonSettings settings_;
  matc::Build build_;
  matc::vulkan::Context context_;
  matc::ComparisonLobes lobes_;
  matc::Lut lobe_lut_;
  std::uint32_t table_size_;
  matc::vulkan::Image ours_table_;
  matc::vulkan::Image lobe_table_;
  matc::vulkan::LutSampler sampler_;
  matc::vulkan::Buffer curve_;
  matc::SpirvWords vertex_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Comparison renders: Monte-Carlo reference, Schlick's split sum, ours"};
  ComparisonSettings settings;
  std::vector<std::string> files;
  app.add_option("files", files, "Material files (.json)")->required();
  add_render_options(
      app, settings,
      "Exit 1 unless ours is closer to the reference than Schlick's for every material");
  app.add_option("--basis", settings.basis, "The Fresnel basis of ours (see matc --help)")
      ->capture_default_str()
      ->check(CLI::IsMember({"extended", "paper"}));
  CLI11_PARSE(app, argc, argv);

  try {
    Renderer renderer(settings);
    fs::create_directories(settings.output);
    fmt::print(
        "Rendered on {}, {}x{} pixels per panel, {} samples per pixel. Mean and max absolute "
        "error in linear radiance over the sphere's pixels and all channels, against the "
        "Monte-Carlo reference (relative: mean error / mean reference radiance) and against "
        "the split sum with the exact Fresnel (the Fresnel's share alone):\n\n"
        "| material | roughness | split sum with | mean | relative | max | Fresnel alone: mean "
        "| Fresnel alone: max |\n|---|---:|---|---:|---:|---:|---:|---:|\n",
        renderer.context().device_name(), settings.size, settings.size, settings.samples);
    bool all_better = true;
    for (const std::string& file : files) {
      const matc::ParseResult parsed = matc::read_material_file(file);
      for (const matc::Diagnostic& diagnostic : parsed.diagnostics.items())
        fmt::print(stderr, "{}\n", matc::format_diagnostic(diagnostic));
      if (!parsed.material) return 1;
      const matc::CompiledMaterial compiled =
          matc::compile_material(*parsed.material, renderer.basis());
      const std::array<Panel, kEstimateCount> estimates = renderer.render(compiled);
      const Panel& reference = estimates[kReference];
      const Panel& radiance = estimates[kPrefilteredRadiance];
      const Panel schlick = radiance.times(estimates[kSchlickFbar]);
      const Panel ours = radiance.times(estimates[kOursFbar]);
      const Panel exact = radiance.times(estimates[kExactFbar]);
      const std::string& name = compiled.material.name;
      write_panels(settings.output / (name + ".png"), {reference.rgb, schlick.rgb, ours.rgb},
                   settings.size, display);
      write_panels(settings.output / (name + "_difference.png"),
                   {difference(schlick, reference), difference(ours, reference)}, settings.size,
                   display_difference);
      write_panels(settings.output / (name + "_fresnel_difference.png"),
                   {difference(schlick, exact), difference(ours, exact)}, settings.size,
                   display_difference);
      const double roughness = compiled.material.roughness.value_or(kDefaultRoughness);
      const std::array<std::pair<const char*, const Panel*>, 3> rows = {
          std::pair{"Schlick's Fresnel", &schlick}, std::pair{"ours", &ours},
          std::pair{"the exact Fresnel", &exact}};
      for (const auto& [label, panel] : rows) {
        const ErrorStats total = error_against(*panel, reference);
        const ErrorStats fresnel = error_against(*panel, exact);
        fmt::print("| {} | {:.3f} | {} | {:.4f} | {:.1f}% | {:.3f} | {} | {} |\n", name, roughness,
                   label, total.mean, 100.0 * total.relative_mean, total.max,
                   panel == &exact ? "-" : fmt::format("{:.4f}", fresnel.mean),
                   panel == &exact ? "-" : fmt::format("{:.3f}", fresnel.max));
      }
      all_better = all_better &&
                   error_against(ours, reference).mean < error_against(schlick, reference).mean;
    }
    if (!validation_clean(renderer.context())) return 1;
    if (settings.check && !all_better) {
      fmt::print(stderr, "matc_render: ours is not closer to the reference than Schlick's\n");
      return 1;
    }
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc_render: error: {}\n", error.what());
    return 1;
  }
  return 0;
}
