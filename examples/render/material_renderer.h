// What the comparison render (render.cpp) and the area-light render (area_light_render.cpp)
// share: a device with our table, the ComparisonLobes table, the sampler, the material's exact
// curve as a buffer, and a full-screen pass of a material's fragment shader whose methods are
// the Estimate slots of panels.h.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compile/compile.h"
#include "emit/build.h"
#include "lut/comparison_lobes.h"
#include "matc/vulkan/buffer.h"
#include "matc/vulkan/image.h"
#include "matc/vulkan/sampler.h"
#include "panels.h"

namespace matc::render {

// A material's fragment shader: comparison_render_source, area_light_render_source or
// coated_render_source.
using MaterialRenderSource = std::string (*)(const Build& build, const CompiledMaterial& compiled,
                                             std::size_t curve_size, std::uint32_t width,
                                             std::uint32_t height);

class MaterialRenderer {
 public:
  // Bindings: 0 our table, 1 the ComparisonLobes table, 2 the sampler, 3 the exact curve (a
  // coated material's: the base lobe in rgb, the coat lobe in a), and with `with_ltc` 4 the LTC
  // table. `methods`: what the fragment shader computes.
  MaterialRenderer(const RenderSettings& settings, const BuildOptions& options,
                   MaterialRenderSource source, std::string fragment_name, bool with_ltc,
                   EstimateMethods methods = {});

  const vulkan::Context& context() const { return context_; }
  runtime::BasisView basis() const { return build_.basis(); }

  // The material file compiled against this renderer's basis; its diagnostics on standard error,
  // nothing for an invalid file.
  std::optional<CompiledMaterial> compile(const std::string& file) const;
  // Every material of an input (a material file, a MaterialX document, a glTF asset) compiled the
  // same way; its diagnostics on standard error, nothing for an invalid input.
  std::optional<std::vector<CompiledMaterial>> compile_all(const std::string& file) const;

  // Whether a render of bare metals (matc_render, matc_area_light_render; `coated` false) or of
  // coated ones (matc_coated_render) draws `compiled`, filmed metals only where `filmed`
  // (matc_render); if not, false with an error on standard error naming the render that does.
  static bool draws(const std::string& file, const CompiledMaterial& compiled, bool coated,
                    bool filmed = false);

  // Every estimate of one material, linear RGB, indexed by method.
  std::vector<Panel> render(const CompiledMaterial& compiled);

 private:
  RenderSettings settings_;
  MaterialRenderSource source_;
  std::string fragment_name_;
  EstimateMethods methods_;
  Build build_;
  vulkan::Context context_;
  ComparisonLobes lobes_;
  Lut lobe_lut_;
  std::uint32_t table_size_;
  vulkan::Image ours_table_;
  vulkan::Image lobe_table_;
  std::optional<vulkan::Image> ltc_table_;
  vulkan::LutSampler sampler_;
  vulkan::Buffer curve_;
  SpirvWords vertex_;
};

}  // namespace matc::render
