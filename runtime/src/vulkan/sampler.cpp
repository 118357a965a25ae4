#include "matc/vulkan/sampler.h"

namespace matc::vulkan {

LutSampler::LutSampler(const Context& context) : device_(context.device()) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.minLod = 0.0f;
  info.maxLod = 0.0f;
  info.unnormalizedCoordinates = VK_FALSE;
  check(vkCreateSampler(device_, &info, nullptr, &sampler_), "vkCreateSampler");
}

LutSampler::~LutSampler() {
  vkDestroySampler(device_, sampler_, nullptr);
}

}  // namespace matc::vulkan
