// The sampler every matc shader expects for the LUT (runtime/lut.h): bilinear filtering,
// clamp-to-edge addressing, a single mip level, normalised coordinates.
#pragma once

#include "matc/vulkan/context.h"

namespace matc::vulkan {

// trilinear_repeat instead: linear filtering between and within mip levels, repeat addressing,
// every level: how an engine samples a textured material's maps (the baked coefficient
// textures of `matc bake`).
enum class SamplerFiltering { bilinear_clamp, trilinear_repeat };

class LutSampler {
 public:
  explicit LutSampler(const Context& context,
                      SamplerFiltering filtering = SamplerFiltering::bilinear_clamp);
  ~LutSampler();
  LutSampler(const LutSampler&) = delete;
  LutSampler& operator=(const LutSampler&) = delete;

  VkSampler handle() const { return sampler_; }

 private:
  VkDevice device_;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace matc::vulkan
