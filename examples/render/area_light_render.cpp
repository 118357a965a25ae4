// Area-light renders on a Vulkan device (lavapipe by default): a sphere on a plane under a
// two-sided rectangular light (templates/glsl/area_light_render.frag), five ways:
//   Monte-Carlo reference with the exact Fresnel | LTC x Schlick's | LTC x ours |
//   LTC x the exact preintegrated Fresnel (LTC's own error alone) | ours at the quality level
//   (shape and Fresnel following the light, ltc_following.h).
// Writes <name>_area.png (the five panels), <name>_area_difference.png (Schlick's and ours
// against the reference, 4x) and <name>_area_fresnel_difference.png (against LTC with the exact
// Fresnel: the Fresnel's share alone), and prints the error table of docs/rendering.md.
//   matc_area_light_render [--size N] [--samples N] [-o DIR] [--check] FILES...
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "compile/compile.h"
#include "emit/build.h"
#include "emit/fullscreen_shaders.h"
#include "material/parse.h"
#include "material_renderer.h"
#include "panels.h"

namespace {

using namespace matc::render;

// The estimates of area_light_render.frag by method number (the Estimate slots they occupy).
constexpr Estimate kLtcExact = kExactFbar;
constexpr Estimate kExactLobeSplit = kPrefilteredRadiance;
constexpr Estimate kLtcSchlick = kSchlickFbar;
constexpr Estimate kLtcOurs = kOursFbar;
constexpr Estimate kQuality = kOursClosedFormFbar;

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Area-light renders: Monte-Carlo reference, LTC with Schlick's Fresnel, with ours"};
  RenderSettings settings;
  settings.output = "render-out";
  std::vector<std::string> files;
  app.add_option("files", files, "Material files (.json)")->required();
  add_render_options(app, settings,
                     "Exit 1 unless, for every material, LTC with ours is no further from the "
                     "reference than LTC with Schlick's, its Fresnel error is at most a tenth of "
                     "Schlick's, and the quality level is no further from the reference than "
                     "LTC with ours");
  CLI11_PARSE(app, argc, argv);

  try {
    MaterialRenderer renderer(settings, matc::one_basis_build(), matc::area_light_render_source,
                              "area_light_render.frag", /*with_ltc=*/true);
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
      const std::optional<matc::CompiledMaterial> material = renderer.compile(file);
      if (!material) return 1;
      const matc::CompiledMaterial& compiled = *material;
      if (!MaterialRenderer::draws(file, compiled, /*coated=*/false, /*filmed=*/true)) return 1;
      // A filmed metal: ours is I_ltc times its own table's Fbar, and it has no quality level.
      const bool filmed = compiled.film_table.has_value();
      const std::vector<Panel> estimates = renderer.render(compiled);
      const Panel& reference = estimates[kReference];
      const Panel& schlick = estimates[kLtcSchlick];
      const Panel& ours = estimates[kLtcOurs];
      const Panel& exact = estimates[kLtcExact];
      const Panel& split = estimates[kExactLobeSplit];
      const Panel& quality = estimates[kQuality];
      const std::string name = compiled.material.name + "_area";
      write_panels(settings.output / (name + ".png"),
                   {reference.rgb, schlick.rgb, ours.rgb, exact.rgb, quality.rgb}, settings.size,
                   display);
      write_difference_panels(settings.output, name, {&schlick, &ours}, reference, exact,
                              settings.size);
      std::vector<ErrorRow> rows = {
          ErrorRow{"Schlick's Fresnel", &schlick},
          ErrorRow{filmed ? "ours (the film's table)" : "ours", &ours},
          ErrorRow{"the exact preintegrated Fresnel", &exact, false},
          ErrorRow{"(no LTC: the exact lobe, the exact preintegrated Fresnel)", &split, false}};
      if (!filmed) {
        rows.push_back(ErrorRow{"ours, quality level (shape and Fresnel following the light)",
                                &quality, false});
      }
      print_error_rows(
          compiled.material.name,
          fmt::format("{:.3f}", compiled.material.roughness.value_or(kDefaultRoughness)), rows,
          reference, exact);
      targets_met =
          targets_met &&
          error_against(ours, reference).mean <= error_against(schlick, reference).mean &&
          error_against(ours, exact).mean <= 0.1 * error_against(schlick, exact).mean &&
          (filmed || error_against(quality, reference).mean <= error_against(ours, reference).mean);
    }
    if (!validation_clean(renderer.context())) return 1;
    if (settings.check && !targets_met) {
      fmt::print(stderr,
                 "matc_area_light_render: LTC with ours misses a target (no further from the "
                 "reference than Schlick's, a tenth of its Fresnel error, the quality level no "
                 "further than the one shape)\n");
      return 1;
    }
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc_area_light_render: error: {}\n", error.what());
    return 1;
  }
  return 0;
}
