// The textured render of docs/rendering.md: a sphere whose reflectivity and edge tint change
// from pixel to pixel (templates/glsl/textured_render.frag), lit by the comparison renders'
// environment, three ways: a Monte-Carlo reference with each pixel's exact conductor Fresnel |
// Schlick's split sum with F0 = r | ours, coefficients from the coefficient table per pixel.
// Four regions: a gradient over the artistic range, g = 0, g = 1, and gold from its RGB index of
// refraction. Writes textured.png, textured_difference.png, textured_fresnel_difference.png and
// prints the error table per region.
// --check compares the Fresnel's share of the error (the split sum's own error is the same for
// both and, at g = 1, can partly cancel Schlick's).
//   matc_textured_render [--size N] [--samples N] [-o DIR] [--check] [--vk-validation]
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "emit/build.h"
#include "emit/fullscreen_shaders.h"
#include "lut/comparison_lobes.h"
#include "matc/vulkan/buffer.h"
#include "matc/vulkan/fullscreen_pass.h"
#include "matc/vulkan/sampler.h"
#include "optics/gulbrandsen.h"
#include "panels.h"

namespace {

namespace fs = std::filesystem;
using namespace matc::render;
using Artistic = std::array<matc::ArtisticParameters, 3>;

constexpr std::array<const char*, 4> kRegions = {
    "gradient: r 0-0.95 across, g 0-1 down (grey)", "g = 0: r = (0.6, 0.5, 0.4)",
    "g = 1: r = (0.95, 0.64, 0.54)", "gold from n + ik at three wavelengths"};

// gold_rgb_ior.json's index, as Gulbrandsen's (r, g).
Artistic gold() {
  const std::array<matc::ComplexIor, 3> ior = {{{0.143, 3.983}, {0.374, 2.385}, {1.442, 1.603}}};
  Artistic out{};
  for (std::size_t c = 0; c < 3; ++c)
    out[c] = matc::ior_to_gulbrandsen(ior[c]);
  return out;
}

// Which region a pixel is in (its quadrant of the image) and its (r, g) there.
std::size_t region_of(std::uint32_t x, std::uint32_t y, std::uint32_t size) {
  return (y * 2 >= size ? 2u : 0u) + (x * 2 >= size ? 1u : 0u);
}

Artistic material_at(std::uint32_t x, std::uint32_t y, std::uint32_t size) {
  const double half = size / 2.0;
  const double s = std::fmod(x, half) / (half - 1.0);  // 0..1 across the quadrant
  const double t = std::fmod(y, half) / (half - 1.0);  // 0..1 down
  const auto grey = [](double r, double g) { return Artistic{{{r, g}, {r, g}, {r, g}}}; };
  switch (region_of(x, y, size)) {
    case 0:
      return grey(0.95 * s, t);
    case 1:
      return Artistic{{{0.6, 0.0}, {0.5, 0.0}, {0.4, 0.0}}};
    case 2:
      return Artistic{{{0.95, 1.0}, {0.64, 1.0}, {0.54, 1.0}}};
    default:
      return gold();
  }
}

// Per pixel: (r, -), (g, -), (n, -), (k, -), as textured_render.frag reads them.
std::vector<float> pixel_materials(std::uint32_t size) {
  std::vector<float> values(std::size_t{size} * size * 16, 0.0f);
  for (std::uint32_t y = 0; y < size; ++y) {
    for (std::uint32_t x = 0; x < size; ++x) {
      const Artistic artistic = material_at(x, y, size);
      float* entry = &values[(std::size_t{y} * size + x) * 16];
      for (std::size_t c = 0; c < 3; ++c) {
        const matc::ComplexIor ior = matc::gulbrandsen_to_ior(artistic[c]);
        entry[c] = static_cast<float>(artistic[c].reflectivity);
        entry[4 + c] = static_cast<float>(artistic[c].edge_tint);
        entry[8 + c] = static_cast<float>(ior.n);
        entry[12 + c] = static_cast<float>(ior.k);
      }
    }
  }
  return values;
}

// The panel restricted to one region's pixels (others become background).
Panel only_region(Panel panel, std::size_t region, std::uint32_t size) {
  for (std::uint32_t y = 0; y < size; ++y)
    for (std::uint32_t x = 0; x < size; ++x)
      if (region_of(x, y, size) != region) panel.sphere[std::size_t{y} * size + x] = false;
  return panel;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Textured render: per-pixel reflectivity and edge tint, reference vs Schlick vs ours"};
  RenderSettings settings;
  add_render_options(app, settings,
                     "Exit 1 unless our Fresnel's error (against the split sum with the exact "
                     "Fresnel) is below Schlick's in every region");
  CLI11_PARSE(app, argc, argv);
  const std::uint32_t size = settings.size + settings.size % 2;  // four equal quadrants
  const std::uint32_t samples = settings.samples;
  const fs::path& output = settings.output;

  try {
    const matc::Build build(matc::one_basis_build());
    const matc::vulkan::Context context(
        matc::vulkan::ContextOptions{settings.validation, settings.device});
    const matc::ComparisonLobes lobes(matc::runtime::shipped_basis().samples());
    const matc::Lut lobe_lut = matc::preintegrate_lut(lobes.view(), {});
    const auto lut_size = static_cast<std::uint32_t>(build.stored_lut().size);
    const matc::vulkan::Image ours_lut(context, lut_size, lut_size, build.stored_lut().texels);
    const matc::vulkan::Image schlick_lut(context, lut_size, lut_size, lobe_lut.texels);
    const auto table_size = static_cast<std::uint32_t>(build.stored_coefficient_table().size());
    const matc::vulkan::Image coefficient_table(
        context, table_size, table_size, matc::rgba_texels(build.stored_coefficient_table()));
    const matc::vulkan::LutSampler sampler(context);
    const std::vector<float> materials = pixel_materials(size);
    matc::vulkan::Buffer material_buffer(context, materials.size() * sizeof(float),
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    material_buffer.write<float>(materials);
    const std::array bindings = {matc::vulkan::Binding::sampled_image(0, ours_lut),
                                 matc::vulkan::Binding::sampled_image(1, schlick_lut),
                                 matc::vulkan::Binding::separate_sampler(2, sampler),
                                 matc::vulkan::Binding::sampled_image(3, coefficient_table),
                                 matc::vulkan::Binding::storage_buffer(4, material_buffer)};
    const matc::SpirvWords vertex = matc::compile_fullscreen_stage(
        matc::fullscreen_vertex_source(), matc::ShaderStage::vertex, "fullscreen.vert");
    const matc::SpirvWords fragment =
        matc::compile_fullscreen_stage(matc::textured_render_source(build, size, size),
                                       matc::ShaderStage::fragment, "textured_render.frag");
    matc::vulkan::FullscreenPass pass(context, vertex, fragment, bindings, size, size,
                                      sizeof(PanelConstants));
    const auto estimates =
        render_estimates(pass, size, samples, static_cast<float>(kDefaultRoughness));
    const Panel& reference = estimates[kReference];
    const Panel& radiance = estimates[kPrefilteredRadiance];
    const Panel schlick = radiance.times(estimates[kSchlickFbar]);
    const Panel ours = radiance.times(estimates[kOursFbar]);
    const Panel closed_form = radiance.times(estimates[kOursClosedFormFbar]);
    const Panel exact = radiance.times(estimates[kExactFbar]);

    fs::create_directories(output);
    write_panels(output / "textured.png", {reference.rgb, schlick.rgb, ours.rgb}, size, display);
    write_difference_panels(output, "textured", {&schlick, &ours}, reference, exact, size);

    fmt::print(
        "Rendered on {}, {}x{} pixels per panel, {} samples per pixel, roughness {}. Mean and "
        "max absolute error in linear radiance over each region's sphere pixels and all "
        "channels, against the Monte-Carlo reference with each pixel's exact Fresnel "
        "(relative: mean error / mean reference radiance) and against the split sum with the "
        "exact Fresnel (the Fresnel's share alone):\n\n"
        "| region | split sum with | mean | relative | max | Fresnel alone: mean | Fresnel "
        "alone: max |\n|---|---|---:|---:|---:|---:|---:|\n",
        context.device_name(), size, size, samples, kDefaultRoughness);
    bool all_better = true;
    for (std::size_t region = 0; region < kRegions.size(); ++region) {
      const Panel region_reference = only_region(reference, region, size);
      const Panel region_exact = only_region(exact, region, size);
      const std::array<std::pair<const char*, const Panel*>, 3> rows = {
          std::pair{"Schlick's Fresnel (F0 = r)", &schlick},
          std::pair{"ours (coefficient table)", &ours},
          std::pair{"ours (coefficient table), closed form", &closed_form}};
      std::array<double, 3> means{};
      for (std::size_t row = 0; row < rows.size(); ++row) {
        const ErrorStats total = error_against(*rows[row].second, region_reference);
        const ErrorStats fresnel = error_against(*rows[row].second, region_exact);
        means[row] = fresnel.mean;
        fmt::print("| {} | {} | {:.4f} | {:.1f}% | {:.3f} | {:.4f} | {:.3f} |\n", kRegions[region],
                   rows[row].first, total.mean, 100.0 * total.relative_mean, total.max,
                   fresnel.mean, fresnel.max);
      }
      all_better = all_better && means[1] < means[0] && means[2] < means[0];
    }
    if (!validation_clean(context)) return 1;
    if (settings.check && !all_better) {
      fmt::print(stderr,
                 "matc_textured_render: our Fresnel is not closer to the exact one than "
                 "Schlick's\n");
      return 1;
    }
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc_textured_render: error: {}\n", error.what());
    return 1;
  }
  return 0;
}
