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

namespace fs = std::filesystem;

using namespace matc::render;

struct ComparisonSettings : RenderSettings {
  std::string basis{matc::runtime::basis_name(matc::runtime::kDefaultBasis)};
};

matc::BuildOptions build_options(const ComparisonSettings& settings) {
  // One layer: the renders bind matc's table and Schlick's lobe table alike.
  return matc::one_basis_build(*matc::runtime::basis_from_name(settings.basis));
}

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
      ->check(CLI::IsMember({"extended", "paper", "f82"}));
  CLI11_PARSE(app, argc, argv);

  try {
    MaterialRenderer renderer(settings, build_options(settings), matc::comparison_render_source,
                              "comparison_render.frag", /*with_ltc=*/false);
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
      const std::optional<matc::CompiledMaterial> material = renderer.compile(file);
      if (!material) return 1;
      const matc::CompiledMaterial& compiled = *material;
      if (!MaterialRenderer::draws(file, compiled, /*coated=*/false, /*filmed=*/true)) return 1;
      const std::vector<Panel> estimates = renderer.render(compiled);
      const Panel& reference = estimates[kReference];
      const Panel& radiance = estimates[kPrefilteredRadiance];
      const Panel schlick = radiance.times(estimates[kSchlickFbar]);
      const Panel ours = radiance.times(estimates[kOursFbar]);
      const Panel closed_form = radiance.times(estimates[kOursClosedFormFbar]);
      const Panel exact = radiance.times(estimates[kExactFbar]);
      const std::string& name = compiled.material.name;
      write_panels(settings.output / (name + ".png"),
                   {reference.rgb, schlick.rgb, ours.rgb, closed_form.rgb}, settings.size, display);
      write_difference_panels(settings.output, name, {&schlick, &ours}, reference, exact,
                              settings.size);
      // A filmed metal's table has no closed form: its row is left out.
      std::vector<ErrorRow> rows = {ErrorRow{"Schlick's Fresnel", &schlick},
                                    ErrorRow{"ours", &ours},
                                    ErrorRow{"ours, closed form (no fetch)", &closed_form},
                                    ErrorRow{"the exact Fresnel", &exact, false}};
      if (compiled.film_table) rows.erase(rows.begin() + 2);
      print_error_rows(
          name, fmt::format("{:.3f}", compiled.material.roughness.value_or(kDefaultRoughness)),
          rows, reference, exact);
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
