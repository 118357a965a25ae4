// The baked-texture render of docs/rendering.md: a ground plane textured with a metal's
// reflectivity and edge-tint maps, seen in perspective so that towards the horizon one pixel
// covers many texels, F at one cosine per pixel, three ways:
//   reference: per pixel, the average over 16 x 16 points of its footprint on the plane of the
//              exact conductor curves of the texels there (bilinearly interpolated, level 0)
//   ours:      the coefficient textures of `matc bake` sampled with trilinear filtering
//   usual:     mip chains of the maps (linear r and g, box-averaged), the same sampler, then
//              the coefficients per pixel from the coefficient table
//   filtered exact: a texture of the texels' exact F at that cosine, its mips box-averaged, the
//              same sampler: what a perfect prefiltered Fresnel would give with this filter.
// Against the reference, all three share the filter's own error (a trilinear footprint is not
// the pixel's); against filtered exact, what remains is how each represents the average curve.
// Both run on the Vulkan device (lavapipe by default), the reference on the CPU. Prints the
// error table by how many texels a pixel covers; writes baked.png and baked_difference.png.
// --check: exit 1 unless ours is closer to the reference than the usual way where pixels cover
// two texels or more.
//   matc_baked_render --reflectivity R.png --edge-tint G.png [--size N] [-o DIR] [--check]
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "bake/bake_inputs.h"
#include "bake/coefficient_textures.h"
#include "emit/build.h"
#include "emit/fullscreen_shaders.h"
#include "matc/vulkan/fullscreen_pass.h"
#include "matc/vulkan/sampler.h"
#include "optics/gulbrandsen.h"
#include "panels.h"

namespace {

namespace fs = std::filesystem;
using matc::render::Panel;
using Rgb = std::array<double, 3>;

constexpr matc::PlaneCamera kCamera{1.0, 0.35, 0.5, 0.5};
constexpr int kReferenceSamples = 16;  // per pixel and axis

// baked_render.frag's plane_uv in double: the texture coordinate where the ray through `pixel`
// (in pixels, top row first) meets the plane, or nothing above the horizon.
std::optional<std::array<double, 2>> plane_uv(double px, double py, std::uint32_t size) {
  const double sx = (2.0 * px / size - 1.0) * kCamera.tan_half_fov;
  const double sy = (1.0 - 2.0 * py / size) * kCamera.tan_half_fov;
  const double c = std::cos(kCamera.pitch), s = std::sin(kCamera.pitch);
  const std::array<double, 3> direction = {sx, c + sy * s, -s + sy * c};
  if (direction[2] >= -1e-4) return std::nullopt;
  const double t = kCamera.height / -direction[2];
  return std::array<double, 2>{t * direction[0] * kCamera.uv_per_unit,
                               t * direction[1] * kCamera.uv_per_unit};
}

// Level 0's exact F at `mu`, per texel and channel, from the maps.
std::vector<Rgb> exact_texels(const matc::BakeInputs& inputs, double mu) {
  std::vector<Rgb> texels(inputs.width * inputs.height);
  for (std::size_t t = 0; t < texels.size(); ++t) {
    for (std::size_t c = 0; c < 3; ++c) {
      const double r = inputs.first.value(t, c), g = inputs.second.value(t, c);
      texels[t][c] = r >= 1.0 ? 1.0 : matc::fresnel_exact(mu, matc::gulbrandsen_to_ior({r, g}));
    }
  }
  return texels;
}

// The reference panel, and how many texels each pixel's footprint spans (0 for sky).
struct Reference {
  Panel panel;
  std::vector<double> texels_per_pixel;
};

Reference reference_panel(const matc::BakeInputs& inputs, const std::vector<Rgb>& exact,
                          std::uint32_t size) {
  Reference reference;
  reference.panel.rgb.assign(std::size_t{size} * size, {});
  reference.panel.sphere.assign(std::size_t{size} * size, false);
  reference.texels_per_pixel.assign(std::size_t{size} * size, 0.0);
  const auto w = static_cast<double>(inputs.width), h = static_cast<double>(inputs.height);
  const auto wrap = [](long i, std::size_t n) {
    return static_cast<std::size_t>(((i % static_cast<long>(n)) + static_cast<long>(n)) %
                                    static_cast<long>(n));
  };
  for (std::uint32_t y = 0; y < size; ++y) {
    for (std::uint32_t x = 0; x < size; ++x) {
      const std::size_t pixel = std::size_t{y} * size + x;
      const auto centre = plane_uv(x + 0.5, y + 0.5, size);
      const auto right = plane_uv(x + 1.5, y + 0.5, size), below = plane_uv(x + 0.5, y + 1.5, size);
      if (!centre || !right || !below) continue;
      reference.panel.sphere[pixel] = true;
      const double du =
          std::hypot(((*right)[0] - (*centre)[0]) * w, ((*right)[1] - (*centre)[1]) * h);
      const double dv =
          std::hypot(((*below)[0] - (*centre)[0]) * w, ((*below)[1] - (*centre)[1]) * h);
      reference.texels_per_pixel[pixel] = std::max(du, dv);
      Rgb sum{};
      for (int j = 0; j < kReferenceSamples; ++j) {
        for (int i = 0; i < kReferenceSamples; ++i) {
          const auto uv =
              *plane_uv(x + (i + 0.5) / kReferenceSamples, y + (j + 0.5) / kReferenceSamples, size);
          // Bilinear between texel centres, repeating, as a sampler reads level 0.
          const double fx = uv[0] * w - 0.5, fy = uv[1] * h - 0.5;
          const double x0 = std::floor(fx), y0 = std::floor(fy);
          const double ax = fx - x0, ay = fy - y0;
          for (int b = 0; b < 4; ++b) {
            const double weight = (b & 1 ? ax : 1 - ax) * (b & 2 ? ay : 1 - ay);
            const std::size_t texel =
                wrap(static_cast<long>(y0) + (b >> 1), inputs.height) * inputs.width +
                wrap(static_cast<long>(x0) + (b & 1), inputs.width);
            for (std::size_t c = 0; c < 3; ++c)
              sum[c] += weight * exact[texel][c];
          }
        }
      }
      for (std::size_t c = 0; c < 3; ++c)
        reference.panel.rgb[pixel][c] = sum[c] / (kReferenceSamples * kReferenceSamples);
    }
  }
  return reference;
}

// An RGB image as RGBA level 0 with its box-filtered mips (the bake's own mip_chain).
template <typename Value>
std::vector<std::vector<float>> mip_chain(std::size_t width, std::size_t height,
                                          const Value& value) {
  std::vector<float> level0(width * height * 4, 1.0f);
  for (std::size_t t = 0; t < width * height; ++t)
    for (std::size_t c = 0; c < 3; ++c)
      level0[4 * t + c] = static_cast<float>(value(t, c));
  return matc::mip_chain(std::move(level0), width, height);
}

// The maps (linear r and g) with box-filtered mips: the usual way.
std::vector<std::vector<float>> map_mips(const matc::BakeInputs& inputs,
                                         const matc::MapSamples& map) {
  return mip_chain(inputs.width, inputs.height,
                   [&](std::size_t t, std::size_t c) { return map.value(t, c); });
}

std::vector<std::span<const float>> spans(const std::vector<std::vector<float>>& levels) {
  return {levels.begin(), levels.end()};
}
std::vector<std::span<const float>> plane_spans(const matc::BakedCoefficients& baked,
                                                std::vector<float> matc::CoefficientLevel::*plane) {
  std::vector<std::span<const float>> levels;
  for (const matc::CoefficientLevel& level : baked.levels)
    levels.emplace_back(level.*plane);
  return levels;
}

Panel read_panel(matc::vulkan::FullscreenPass& pass, int method, float mu, std::uint32_t size) {
  struct Constants {
    std::int32_t method;
    float mu;
  } constants{method, mu};
  pass.draw(std::as_bytes(std::span(&constants, 1)));
  const std::vector<float> pixels = pass.read_pixels();
  Panel panel;
  for (std::size_t p = 0; p < std::size_t{size} * size; ++p) {
    panel.rgb.push_back({pixels[4 * p], pixels[4 * p + 1], pixels[4 * p + 2]});
    panel.sphere.push_back(pixels[4 * p + 3] > 0.5f);
  }
  return panel;
}

// Mean and max |panel - reference| over the pixels whose footprint spans [low, high) texels.
matc::render::ErrorStats band_error(const Panel& panel, const Reference& reference, double low,
                                    double high) {
  Panel band = reference.panel;
  for (std::size_t p = 0; p < band.sphere.size(); ++p)
    band.sphere[p] = band.sphere[p] && reference.texels_per_pixel[p] >= low &&
                     reference.texels_per_pixel[p] < high;
  return matc::render::error_against(panel, band);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Baked coefficient textures vs the maps' own mips, against averaged exact curves"};
  matc::render::RenderSettings settings;
  std::string reflectivity, edge_tint;
  std::vector<double> cosines = {0.2, 0.5};
  app.add_option("--reflectivity", reflectivity, "Reflectivity map (sRGB PNG)")->required();
  app.add_option("--edge-tint", edge_tint, "Edge-tint map (sRGB PNG)")->required();
  app.add_option("--mu", cosines, "Cosines at which F is rendered")->delimiter(',');
  matc::render::add_render_options(
      app, settings,
      "Exit 1 unless ours is closer to the reference than the usual way where a pixel covers "
      "2 texels or more");
  CLI11_PARSE(app, argc, argv);
  const std::uint32_t size = settings.size;

  try {
    matc::BakeAsset asset;
    for (auto [map, quantity, file] :
         {std::tuple{&asset.first, matc::MapQuantity::reflectivity, reflectivity},
          std::tuple{&asset.second, matc::MapQuantity::edge_tint, edge_tint}}) {
      map->quantity = quantity;
      map->file = file;
      map->resolved = file;
    }
    matc::Diagnostics diagnostics;
    const auto inputs = matc::load_bake_inputs(asset, diagnostics);
    if (!inputs) throw std::runtime_error(diagnostics.items().front().message);
    matc::BakeOptions options;
    options.f0 = true;
    const matc::BakedCoefficients baked = matc::bake_coefficients(*inputs, options);

    const matc::Build build(matc::one_basis_build());
    const matc::vulkan::Context context(
        matc::vulkan::ContextOptions{settings.validation, settings.device});
    const auto width = static_cast<std::uint32_t>(inputs->width);
    const auto height = static_cast<std::uint32_t>(inputs->height);
    const matc::vulkan::Image f0(context, width, height,
                                 plane_spans(baked, &matc::CoefficientLevel::f0));
    const matc::vulkan::Image c2(context, width, height,
                                 plane_spans(baked, &matc::CoefficientLevel::c2));
    const matc::vulkan::Image c3(context, width, height,
                                 plane_spans(baked, &matc::CoefficientLevel::c3));
    const auto r_levels = map_mips(*inputs, inputs->first);
    const auto g_levels = map_mips(*inputs, inputs->second);
    const matc::vulkan::Image r_map(context, width, height, spans(r_levels));
    const matc::vulkan::Image g_map(context, width, height, spans(g_levels));
    const auto table_size = static_cast<std::uint32_t>(build.stored_coefficient_table().size());
    const matc::vulkan::Image table(context, table_size, table_size,
                                    matc::rgba_texels(build.stored_coefficient_table()));
    const matc::vulkan::LutSampler trilinear(context,
                                             matc::vulkan::SamplerFiltering::trilinear_repeat);
    const matc::vulkan::LutSampler table_sampler(context);
    const matc::SpirvWords vertex = matc::compile_fullscreen_stage(
        matc::fullscreen_vertex_source(), matc::ShaderStage::vertex, "fullscreen.vert");
    const matc::SpirvWords fragment =
        matc::compile_fullscreen_stage(matc::baked_render_source(build, kCamera, size, size),
                                       matc::ShaderStage::fragment, "baked_render.frag");
    const auto bindings_with = [&](const matc::vulkan::Image& exact_fresnel) {
      return std::array{matc::vulkan::Binding::sampled_image(0, f0),
                        matc::vulkan::Binding::sampled_image(1, c2),
                        matc::vulkan::Binding::sampled_image(2, c3),
                        matc::vulkan::Binding::sampled_image(3, r_map),
                        matc::vulkan::Binding::sampled_image(4, g_map),
                        matc::vulkan::Binding::sampled_image(5, table),
                        matc::vulkan::Binding::separate_sampler(6, trilinear),
                        matc::vulkan::Binding::separate_sampler(7, table_sampler),
                        matc::vulkan::Binding::sampled_image(8, exact_fresnel)};
    };

    fmt::print(
        "Rendered on {}: a {} x {} map pair on a plane in perspective, {} x {} pixels, F at "
        "each cosine per pixel. Mean and max |F - reference| over pixels grouped by how many "
        "texels their footprint spans; reference: per pixel, the average over {} points of "
        "its footprint of the texels' exact curves.\n\n"
        "| mu | texels per pixel | pixels | ours (coefficient mips): mean / max | usual (mips "
        "of r, g, then solve): mean / max | filtered exact: mean / max | ours vs filtered exact: "
        "mean / max | usual vs filtered exact: mean / max |\n"
        "|---:|---|---:|---:|---:|---:|---:|---:|\n",
        context.device_name(), width, height, size, size, kReferenceSamples * kReferenceSamples);
    bool better = true;
    fs::create_directories(settings.output);
    for (const double mu : cosines) {
      const std::vector<Rgb> exact = exact_texels(*inputs, mu);
      const Reference reference = reference_panel(*inputs, exact, size);
      const auto exact_levels = mip_chain(
          inputs->width, inputs->height, [&](std::size_t t, std::size_t c) { return exact[t][c]; });
      const matc::vulkan::Image exact_image(context, width, height, spans(exact_levels));
      const auto bindings = bindings_with(exact_image);
      matc::vulkan::FullscreenPass pass(context, vertex, fragment, bindings, size, size, 8);
      const Panel ours = read_panel(pass, 0, static_cast<float>(mu), size);
      const Panel usual = read_panel(pass, 1, static_cast<float>(mu), size);
      const Panel filtered = read_panel(pass, 2, static_cast<float>(mu), size);
      const std::array<std::array<double, 2>, 3> bands = {{{0.0, 2.0}, {2.0, 8.0}, {8.0, 1e30}}};
      for (const auto& [low, high] : bands) {
        std::size_t pixels = 0;
        for (std::size_t p = 0; p < reference.texels_per_pixel.size(); ++p)
          pixels += reference.panel.sphere[p] && reference.texels_per_pixel[p] >= low &&
                    reference.texels_per_pixel[p] < high;
        const auto ours_error = band_error(ours, reference, low, high);
        const auto usual_error = band_error(usual, reference, low, high);
        const auto filtered_error = band_error(filtered, reference, low, high);
        Reference filtered_reference = reference;
        filtered_reference.panel.rgb = filtered.rgb;
        const auto ours_filtered = band_error(ours, filtered_reference, low, high);
        const auto usual_filtered = band_error(usual, filtered_reference, low, high);
        fmt::print(
            "| {} | {} | {} | {:.4f} / {:.3f} | {:.4f} / {:.3f} | {:.4f} / {:.3f} | {:.4f} / "
            "{:.3f} | {:.4f} / {:.3f} |\n",
            mu, high > 1e29 ? fmt::format("{} or more", low) : fmt::format("{}-{}", low, high),
            pixels, ours_error.mean, ours_error.max, usual_error.mean, usual_error.max,
            filtered_error.mean, filtered_error.max, ours_filtered.mean, ours_filtered.max,
            usual_filtered.mean, usual_filtered.max);
        if (low >= 2.0 && pixels > 0)
          better = better && ours_error.mean < usual_error.mean &&
                   ours_filtered.mean < usual_filtered.mean;
      }
      const std::string suffix = fmt::format("_mu{}", static_cast<int>(std::lround(mu * 100)));
      matc::render::write_panels(settings.output / ("baked" + suffix + ".png"),
                                 {reference.panel.rgb, filtered.rgb, ours.rgb, usual.rgb}, size,
                                 matc::render::display);
      matc::render::write_panels(settings.output / ("baked_difference" + suffix + ".png"),
                                 {matc::render::difference(ours, reference.panel),
                                  matc::render::difference(usual, reference.panel)},
                                 size, matc::render::display_difference);
    }
    if (!matc::render::validation_clean(context)) return 1;
    if (settings.check && !better) {
      fmt::print(stderr,
                 "matc_baked_render: ours is not closer to the reference than the usual "
                 "way where minification matters\n");
      return 1;
    }
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc_baked_render: error: {}\n", error.what());
    return 1;
  }
  return 0;
}
