// The coated comparison render on a Vulkan device (lavapipe by default): the comparison render's
// sphere under its sky for a coated metal (docs/coating.md), image-based lighting three ways
// (templates/glsl/coated_render.frag):
//   Monte-Carlo reference, both lobes with their exact curves | the engines' F0-in-coat Schlick
//   under the same layering (Filament's) | three.js's clear coat over the metal's Schlick curve in
//   air (as its glTF loader builds a KHR_materials_clearcoat metal) | ours.
// Each split sum is two: every lobe's prefiltered radiance (at its own roughness) times its
// preintegrated Fresnel. Writes <name>.png (the three panels), <name>_difference.png and
// <name>_fresnel_difference.png as matc_render does, and prints the error table of
// docs/rendering.md.
// FILES are material files or documents (a glTF asset, a MaterialX document): every coated metal
// of each is drawn.
//   matc_coated_render [--size N] [--samples N] [-o DIR] [--check] FILES...
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "compile/compile.h"
#include "emit/build.h"
#include "emit/fullscreen_shaders.h"
#include "matc/runtime/coat.h"
#include "material_renderer.h"
#include "panels.h"

namespace {

using namespace matc::render;

// coated_render.frag's methods.
enum CoatedEstimate : std::int32_t {
  kCoatedReference = 0,
  kBaseRadiance = 1,
  kCoatRadiance = 2,
  kExactUnderCoat = 3,
  kExactCoat = 4,
  kExactInAir = 5,
  kOursBaseFbar = 6,
  kOursCoatFbar = 7,
  kEngineBaseFbar = 8,
  kCoatTint = 9,
  kThreeJsBaseFbar = 10,
  kThreeJsCoatFbar = 11,
  kCoatedEstimateCount = 12,
};

// Both lobes' split sums: each lobe's radiance times its preintegrated Fresnel, added.
Panel two_lobes(const std::vector<Panel>& estimates, const Panel& base, const Panel& coat) {
  Panel sum = estimates[kBaseRadiance].times(base);
  const Panel coat_part = estimates[kCoatRadiance].times(coat);
  for (std::size_t i = 0; i < sum.rgb.size(); ++i) {
    if (!sum.sphere[i]) continue;  // the background keeps its colour
    for (std::size_t c = 0; c < 3; ++c)
      sum.rgb[i][c] += coat_part.rgb[i][c];
  }
  return sum;
}

// The split sums' Fresnel factors with the exact curves: the exact preintegrated curves layered
// as the shaders layer theirs (runtime::layered_base, the coat's tint at NdotV): what any split
// sum of this layering does at best. Returns the base lobe's and the coat lobe's.
std::pair<Panel, Panel> exact_factors(const std::vector<Panel>& estimates, double weight) {
  Panel base = estimates[kExactUnderCoat], coat = estimates[kExactCoat];
  for (std::size_t i = 0; i < base.rgb.size(); ++i) {
    const double f = estimates[kExactCoat].rgb[i][0];
    base.rgb[i] = matc::runtime::layered_base(estimates[kExactInAir].rgb[i],
                                              estimates[kExactUnderCoat].rgb[i],
                                              estimates[kCoatTint].rgb[i], f, weight);
    coat.rgb[i] = {weight * f, weight * f, weight * f};
  }
  return {base, coat};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Coated comparison renders: Monte-Carlo reference, the engines' F0-in-coat Schlick, "
      "three.js's clear coat, ours"};
  RenderSettings settings;
  std::vector<std::string> files;
  app.add_option("files", files,
                 "Material files (.json) or documents (.gltf, .glb, .mtlx): their coated metals")
      ->required();
  add_render_options(app, settings,
                     "Exit 1 unless ours is closer to the reference than the engines' F0-in-coat "
                     "Schlick and three.js's clear coat for every material");
  CLI11_PARSE(app, argc, argv);

  try {
    MaterialRenderer renderer(settings, matc::one_basis_build(), matc::coated_render_source,
                              "coated_render.frag", /*with_ltc=*/false,
                              {kCoatedEstimateCount, kOursBaseFbar});  // lookups from 6
    std::filesystem::create_directories(settings.output);
    fmt::print(
        "Rendered on {}, {}x{} pixels per panel, {} samples per pixel. Mean and max absolute "
        "error in linear radiance over the sphere's pixels and all channels, against the "
        "Monte-Carlo reference of both lobes (relative: mean error / mean reference radiance) "
        "and against the split sums with the exact curves (the Fresnel's share alone):\n\n"
        "| material | roughness (base, coat) | split sums with | mean | relative | max | "
        "Fresnel alone: mean | Fresnel alone: max |\n"
        "|---|---:|---|---:|---:|---:|---:|---:|\n",
        renderer.context().device_name(), settings.size, settings.size, settings.samples);
    bool all_better = true;
    for (const std::string& file : files) {
      const std::optional<std::vector<matc::CompiledMaterial>> inputs = renderer.compile_all(file);
      if (!inputs) return 1;
      std::vector<const matc::CompiledMaterial*> coated;
      for (const matc::CompiledMaterial& compiled : *inputs)
        if (compiled.coat) coated.push_back(&compiled);
      // A material file names one material, which must be coated; a document may hold bare ones.
      if (coated.empty() && !inputs->empty() &&
          !MaterialRenderer::draws(file, inputs->front(), /*coated=*/true))
        return 1;
      for (const matc::CompiledMaterial* each : coated) {
        const matc::CompiledMaterial& compiled = *each;
        const std::vector<Panel> estimates = renderer.render(compiled);
        const Panel& reference = estimates[kCoatedReference];
        const Panel engine =
            two_lobes(estimates, estimates[kEngineBaseFbar], estimates[kOursCoatFbar]);
        const Panel three =
            two_lobes(estimates, estimates[kThreeJsBaseFbar], estimates[kThreeJsCoatFbar]);
        const Panel ours = two_lobes(estimates, estimates[kOursBaseFbar], estimates[kOursCoatFbar]);
        const auto [exact_base, exact_coat] = exact_factors(estimates, compiled.coat->input.weight);
        const Panel exact = two_lobes(estimates, exact_base, exact_coat);
        const std::string& name = compiled.material.name;
        write_panels(settings.output / (name + ".png"),
                     {reference.rgb, engine.rgb, three.rgb, ours.rgb}, settings.size, display);
        write_difference_panels(settings.output, name, {&engine, &three, &ours}, reference, exact,
                                settings.size);
        const std::array<ErrorRow, 4> rows = {
            ErrorRow{"F0-in-coat Schlick (Filament)", &engine},
            ErrorRow{"F0 in air under the coat (three.js)", &three, false}, ErrorRow{"ours", &ours},
            ErrorRow{"the exact curves", &exact, false}};
        print_error_rows(
            name,
            fmt::format("{:.2f}, {:.2f}", compiled.material.roughness.value_or(kDefaultRoughness),
                        compiled.coat->input.roughness),
            rows, reference, exact);
        const double ours_error = error_against(ours, reference).mean;
        all_better = all_better && ours_error < error_against(engine, reference).mean &&
                     ours_error < error_against(three, reference).mean;
      }
    }
    if (!validation_clean(renderer.context())) return 1;
    if (settings.check && !all_better) {
      fmt::print(stderr,
                 "matc_coated_render: ours is not closer to the reference than the engines' "
                 "F0-in-coat Schlick and three.js's clear coat\n");
      return 1;
    }
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc_coated_render: error: {}\n", error.what());
    return 1;
  }
  return 0;
}
