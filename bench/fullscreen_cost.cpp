// The cost of our Fresnel against Schlick's in a 1280x720 full-screen fragment pass on a Vulkan
// device (lavapipe unless --device picks another): the same table fetch, target and pass for both,
// only the Fresnel differs. Prints the table of docs/performance.md (bench/run-benchmarks.sh).
//   matc_fullscreen_cost [--device NAME] [--frames N] [--warmup N]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "compile/compile.h"
#include "emit/build.h"
#include "emit/fullscreen_shaders.h"
#include "lut/comparison_lobes.h"
#include "matc/runtime/ltc.h"
#include "matc/vulkan/fullscreen_pass.h"
#include "matc/vulkan/sampler.h"
#include "material/parse.h"

namespace {

constexpr std::uint32_t kWidth = 1280;
constexpr std::uint32_t kHeight = 720;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Timings {
  std::vector<double> device_ms;
  std::vector<double> wall_ms;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"720p full-screen pass: our Fresnel against Schlick's on a Vulkan device"};
  std::string device_name;
  int frames = 200;
  int warmup = 20;
  app.add_option("--device", device_name, "A substring of the Vulkan device's name");
  app.add_option("--frames", frames, "Timed frames per variant")->check(CLI::Range(5, 100000));
  app.add_option("--warmup", warmup, "Untimed frames first")->check(CLI::Range(1, 1000));
  CLI11_PARSE(app, argc, argv);

  const matc::ParseResult parsed =
      matc::read_material_file(MATC_EXAMPLES_DIR "/figure2_edge_tint.json");
  const matc::CompiledMaterial material =
      matc::compile_material(*parsed.material, matc::runtime::shipped_basis());
  const matc::Build build(matc::one_basis_build());
  const matc::ComparisonLobes lobes(matc::runtime::shipped_basis().samples());
  const matc::Lut lobe_lut = matc::preintegrate_lut(lobes.view(), {});

  const matc::vulkan::Context context(matc::vulkan::ContextOptions{false, device_name});
  const auto size = static_cast<std::uint32_t>(build.stored_lut().size);
  const matc::vulkan::Image ours_table(context, size, size, build.stored_lut().texels);
  const matc::vulkan::Image schlick_table(context, size, size, lobe_lut.texels);
  // The coefficient table as RGBA32F (.xy used): the same filtering as an RG texture.
  const matc::CoefficientTable& coefficients = build.stored_coefficient_table();
  const auto table_size = static_cast<std::uint32_t>(coefficients.size());
  const matc::vulkan::Image coefficient_table(context, table_size, table_size,
                                              matc::rgba_texels(coefficients));
  const matc::runtime::LtcTableView ltc = matc::runtime::shipped_ltc_table();
  const matc::vulkan::Image ltc_table(context, static_cast<std::uint32_t>(ltc.size),
                                      static_cast<std::uint32_t>(ltc.size), ltc.texels);
  // The textured metal's reflectivity and edge-tint maps (the same one at both bindings): values
  // spread over [0, 0.95] so the table's texture coordinates vary from pixel to pixel.
  constexpr std::uint32_t kMapSize = 64;
  std::vector<float> map_texels;
  for (std::uint32_t i = 0; i < kMapSize * kMapSize; ++i) {
    for (const double scale : {3.1, 5.3, 7.7})
      map_texels.push_back(static_cast<float>(0.95 * std::fmod(i * scale / kMapSize, 1.0)));
    map_texels.push_back(1.0f);
  }
  const matc::vulkan::Image material_map(context, kMapSize, kMapSize, map_texels);
  const matc::vulkan::LutSampler sampler(context);
  const matc::SpirvWords vertex = matc::compile_fullscreen_stage(
      matc::fullscreen_vertex_source(), matc::ShaderStage::vertex, "fullscreen.vert");

  struct Variant {
    const char* label;
    matc::FresnelQuantity quantity;
  };
  const std::array<Variant, 5> variants = {
      Variant{"image-based light: environment times Fbar (two RGBA32F fetches)",
              matc::FresnelQuantity::preintegrated},
      Variant{"Fbar without a fetch: ours in closed form, Schlick's by Karis' approximation",
              matc::FresnelQuantity::preintegrated_closed_form},
      Variant{"F alone (no fetch)", matc::FresnelQuantity::direct},
      Variant{"one GGX light: D, Smith V, F, NdotL (no fetch)", matc::FresnelQuantity::ggx_light},
      Variant{"one quad light, LTC (two RGBA32F fetches, the polygon integral)",
              matc::FresnelQuantity::quad_light}};

  fmt::print(
      "Measured on {}, {} CPU thread(s) on the host ({} frames after {} warm-up frames per "
      "variant, interleaved; medians):\n\n"
      "| pass (1280x720, material figure2_edge_tint) | Schlick (ms) | ours (ms) | ours / "
      "Schlick | ours, coefficient table (ms) | table / Schlick | host: Schlick (ms) | host: ours "
      "(ms) | host: ours / Schlick | host: table (ms) | host: table / Schlick |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
      context.device_name(), std::thread::hardware_concurrency(), frames, warmup);
  std::array<std::array<double, 3>, variants.size()> creation_ms{};
  for (const Variant& variant : variants) {
    // Schlick, ours (compiled), ours (coefficient table), in that order.
    constexpr std::array kModels = {matc::FresnelModel::schlick, matc::FresnelModel::ours,
                                    matc::FresnelModel::table};
    std::array<std::unique_ptr<matc::vulkan::FullscreenPass>, kModels.size()> passes;
    for (std::size_t which = 0; which < kModels.size(); ++which) {
      const bool schlick = kModels[which] == matc::FresnelModel::schlick;
      const matc::SpirvWords fragment =
          matc::compile_fullscreen_stage(matc::cost_pass_source(build, material, kModels[which],
                                                                variant.quantity, kWidth, kHeight),
                                         matc::ShaderStage::fragment, "cost_pass.frag");
      // The image-light pass's prefiltered environment reads the material map: any RGBA32F
      // image costs the same fetch.
      std::vector<matc::vulkan::Binding> bindings;
      for (const matc::CostPassBinding& binding :
           matc::cost_pass_bindings(kModels[which], variant.quantity)) {
        switch (binding.resource) {
          case matc::CostPassResource::sampler:
            bindings.push_back(matc::vulkan::Binding::separate_sampler(binding.binding, sampler));
            continue;
          case matc::CostPassResource::table:
            bindings.push_back(matc::vulkan::Binding::sampled_image(
                binding.binding, schlick ? schlick_table : ours_table));
            continue;
          case matc::CostPassResource::coefficient_table:
            bindings.push_back(
                matc::vulkan::Binding::sampled_image(binding.binding, coefficient_table));
            continue;
          case matc::CostPassResource::ltc_table:
            bindings.push_back(matc::vulkan::Binding::sampled_image(binding.binding, ltc_table));
            continue;
          case matc::CostPassResource::material_map:
          case matc::CostPassResource::environment:
          case matc::CostPassResource::film_table:
            bindings.push_back(matc::vulkan::Binding::sampled_image(binding.binding, material_map));
            continue;
        }
      }
      const auto start = std::chrono::steady_clock::now();
      passes[which] = std::make_unique<matc::vulkan::FullscreenPass>(context, vertex, fragment,
                                                                     bindings, kWidth, kHeight);
      passes[which]->draw();  // drivers may compile at the first draw
      creation_ms[&variant - variants.data()][which] =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
    }
    std::array<Timings, kModels.size()> timings;
    for (int frame = 0; frame < warmup + frames; ++frame) {
      for (std::size_t which = 0; which < kModels.size(); ++which) {
        const matc::vulkan::FrameTime time = passes[which]->draw();
        if (frame < warmup) continue;
        timings[which].device_ms.push_back(time.device_ms);
        timings[which].wall_ms.push_back(time.wall_ms);
      }
    }
    // Device timestamps around the pass (NaN where the queue has none), then the host's
    // submit-to-fence time, which adds the same submission overhead to both.
    const double schlick = median(timings[0].device_ms);
    const double ours = median(timings[1].device_ms);
    const double table = median(timings[2].device_ms);
    const double schlick_host = median(timings[0].wall_ms);
    const double ours_host = median(timings[1].wall_ms);
    const double table_host = median(timings[2].wall_ms);
    fmt::print(
        "| {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | "
        "{:.3f} |\n",
        variant.label, schlick, ours, ours / schlick, table, table / schlick, schlick_host,
        ours_host, ours_host / schlick_host, table_host, table_host / schlick_host);
  }
  // Creating a pass compiles its shaders on the device (lavapipe: LLVM), once per pipeline.
  fmt::print(
      "\nPipeline creation and first frame (the device's shader compile), one run:\n\n"
      "| pass | Schlick (ms) | ours (ms) | ours, coefficient table (ms) |\n"
      "|---|---:|---:|---:|\n");
  for (std::size_t v = 0; v < variants.size(); ++v) {
    fmt::print("| {} | {:.0f} | {:.0f} | {:.0f} |\n", variants[v].label, creation_ms[v][0],
               creation_ms[v][1], creation_ms[v][2]);
  }
  return 0;
}
