// The sampler every matc shader expects for the LUT (runtime/lut.h): bilinear filtering,
// clamp-to-edge addressing, a single mip level, normalised coordinates.
#pragma once

#include "matc/vulkan/context.h"

namespace matc::vulkan {

class LutSampler {
 public:
  explicit LutSampler(const Context& context);
  ~LutSampler();
  LutSampler(const LutSampler&) = delete;
  LutSampler& operator=(const LutSampler&) = delete;

  VkSampler handle() const { return sampler_; }

 private:
  VkDevice device_;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace matc::vulkan
