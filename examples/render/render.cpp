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
#include <stb_image_write.h>
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

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kCurveSize = 1024;
constexpr std::uint32_t kSamplesPerPass = 64;
constexpr double kDifferenceScale = 4.0;
constexpr double kDefaultRoughness = 0.3;

// The estimates comparison_render.frag computes, by its `method` number.
enum Estimate : std::int32_t {
  kReference = 0,
  kPrefilteredRadiance = 1,
  kExactFbar = 2,
  kSchlickFbar = 3,
  kOursFbar = 4,
  kEstimateCount = 5,
};

// Matches the push-constant block of comparison_render.frag.
struct PanelConstants {
  std::int32_t method;
  std::uint32_t first_sample;
  std::uint32_t sample_count;
  std::uint32_t total_samples;
  float roughness;
};

// Linear RGB per pixel; background pixels flagged.
struct Panel {
  std::vector<std::array<double, 3>> rgb;
  std::vector<bool> sphere;

  // The split sum: this (prefiltered radiance) times a preintegrated Fresnel, per pixel.
  Panel times(const Panel& fresnel) const {
    Panel product = *this;
    for (std::size_t i = 0; i < rgb.size(); ++i) {
      if (!sphere[i]) continue;  // the background keeps its colour
      for (std::size_t c = 0; c < 3; ++c)
        product.rgb[i][c] *= fresnel.rgb[i][c];
    }
    return product;
  }
};

struct ErrorStats {
  double mean = 0.0;
  double max = 0.0;
  double relative_mean = 0.0;  // mean |difference| / mean reference
};

// A value in [0, 1] through the sRGB transfer function, to 8 bits.
std::uint8_t srgb_8bit(double value) {
  const double x = std::clamp(value, 0.0, 1.0);
  const double encoded = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(encoded * 255.0));
}

// Narkowicz's fit of the ACES filmic curve, then sRGB.
std::uint8_t display(double linear) {
  const double x = std::max(linear, 0.0);
  return srgb_8bit(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14));
}

std::uint8_t display_difference(double difference) {
  return srgb_8bit(difference * kDifferenceScale);
}

void write_png(const fs::path& path, std::uint32_t width, std::uint32_t height,
               const std::vector<std::uint8_t>& rgb) {
  std::string bytes;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(size));
      },
      &bytes, static_cast<int>(width), static_cast<int>(height), 3, rgb.data(),
      static_cast<int>(width * 3));
  if (bytes.empty()) throw std::runtime_error("cannot encode " + path.string());
  const fs::path temporary = path.string() + ".tmp";
  std::ofstream(temporary, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  fs::rename(temporary, path);
}

// Panels side by side, each through `to_display`.
template <typename ToDisplay>
std::vector<std::uint8_t> side_by_side(
    const std::vector<std::vector<std::array<double, 3>>>& panels, std::uint32_t size,
    ToDisplay to_display) {
  const std::size_t width = size * panels.size();
  std::vector<std::uint8_t> rgb(width * size * 3);
  for (std::size_t p = 0; p < panels.size(); ++p) {
    for (std::size_t y = 0; y < size; ++y) {
      for (std::size_t x = 0; x < size; ++x) {
        for (std::size_t c = 0; c < 3; ++c)
          rgb[(y * width + p * size + x) * 3 + c] = to_display(panels[p][y * size + x][c]);
      }
    }
  }
  return rgb;
}

// |panel - reference| per pixel and channel; zero on the background.
std::vector<std::array<double, 3>> difference(const Panel& panel, const Panel& reference) {
  std::vector<std::array<double, 3>> result(panel.rgb.size(), {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < panel.rgb.size(); ++i) {
    if (!reference.sphere[i]) continue;
    for (std::size_t c = 0; c < 3; ++c)
      result[i][c] = std::abs(panel.rgb[i][c] - reference.rgb[i][c]);
  }
  return result;
}

ErrorStats error_against(const Panel& panel, const Panel& reference) {
  ErrorStats stats;
  double reference_sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < panel.rgb.size(); ++i) {
    if (!reference.sphere[i]) continue;
    for (std::size_t c = 0; c < 3; ++c) {
      const double difference = std::abs(panel.rgb[i][c] - reference.rgb[i][c]);
      stats.mean += difference;
      stats.max = std::max(stats.max, difference);
      reference_sum += reference.rgb[i][c];
      ++count;
    }
  }
  stats.relative_mean = stats.mean / std::max(reference_sum, 1e-30);
  stats.mean /= static_cast<double>(std::max<std::size_t>(count, 1));
  return stats;
}

struct RenderSettings {
  std::uint32_t size = 256;
  std::uint32_t samples = 1024;
  fs::path output = "render-out";
  bool check = false;
  bool validation = false;
  std::string device;
  std::string basis{matc::runtime::basis_name(matc::runtime::kDefaultBasis)};
};

matc::BuildOptions build_options(const RenderSettings& settings) {
  matc::BuildOptions options;
  options.basis = *matc::runtime::basis_from_name(settings.basis);
  return options;
}

class Renderer {
 public:
  explicit Renderer(const RenderSettings& settings)
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
    std::array<Panel, kEstimateCount> panels;
    const std::size_t pixels = std::size_t{settings_.size} * settings_.size;
    for (std::int32_t method = 0; method < kEstimateCount; ++method) {
      std::vector<std::array<double, 4>> sums(pixels, {0.0, 0.0, 0.0, 0.0});
      // Table lookups are exact in one pass; Monte-Carlo estimates take all the samples.
      const std::uint32_t samples = method >= kSchlickFbar ? 1 : settings_.samples;
      for (std::uint32_t first = 0; first < samples; first += kSamplesPerPass) {
        const PanelConstants constants{method, first, std::min(kSamplesPerPass, samples - first),
                                       samples, roughness};
        pass.draw(std::as_bytes(std::span(&constants, 1)));
        const std::vector<float> result = pass.read_pixels();
        for (std::size_t i = 0; i < pixels; ++i) {
          for (std::size_t c = 0; c < 4; ++c)
            sums[i][c] += result[4 * i + c];
        }
      }
      Panel& panel = panels[method];
      panel.rgb.resize(pixels);
      panel.sphere.resize(pixels);
      for (std::size_t i = 0; i < pixels; ++i) {
        panel.sphere[i] = sums[i][3] > 0.0;
        for (std::size_t c = 0; c < 3; ++c)
          panel.rgb[i][c] = sums[i][3] != 0.0 ? sums[i][c] / sums[i][3] : 0.0;
      }
    }
    return panels;
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
  matc::vulkan::LutSampler sampler_;
  matc::vulkan::Buffer curve_;
  matc::SpirvWords vertex_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Comparison renders: Monte-Carlo reference, Schlick's split sum, ours"};
  RenderSettings settings;
  std::vector<std::string> files;
  app.add_option("files", files, "Material files (.json)")->required();
  app.add_option("--size", settings.size, "Width and height of each panel in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 2048));
  app.add_option("--samples", settings.samples, "Samples per pixel (reference and prefiltering)")
      ->capture_default_str()
      ->check(CLI::Range(16, 1 << 20));
  app.add_option("-o,--output", settings.output, "Where the PNG files go")->capture_default_str();
  app.add_flag("--check", settings.check,
               "Exit 1 unless ours is closer to the reference than Schlick's for every material");
  app.add_flag("--vk-validation", settings.validation, "Enable the Khronos validation layer");
  app.add_option("--device", settings.device, "A substring of the Vulkan device's name");
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
      write_png(settings.output / (name + ".png"), settings.size * 3, settings.size,
                side_by_side({reference.rgb, schlick.rgb, ours.rgb}, settings.size, display));
      write_png(settings.output / (name + "_difference.png"), settings.size * 2, settings.size,
                side_by_side({difference(schlick, reference), difference(ours, reference)},
                             settings.size, display_difference));
      write_png(settings.output / (name + "_fresnel_difference.png"), settings.size * 2,
                settings.size,
                side_by_side({difference(schlick, exact), difference(ours, exact)}, settings.size,
                             display_difference));
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
    for (const std::string& message : renderer.context().validation_messages())
      fmt::print(stderr, "validation layer: {}\n", message);
    if (!renderer.context().validation_messages().empty()) return 1;
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
