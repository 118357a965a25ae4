#include "matc/vulkan/sampler.h"

namespace matc::vulkan {

LutSampler::LutSampler(const Context& context, SamplerFiltering filtering)
    : device_(context.device()) {
  const bool trilinear = filtering == SamplerFiltering::trilinear_repeat;
  const VkSamplerAddressMode address =
      trilinear ? VK_SAMPLER_ADDRESS_MODE_REPEAT : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = trilinear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = address;
  info.addressModeV = address;
  info.addressModeW = address;
  info.minLod = 0.0f;
  info.maxLod = trilinear ? VK_LOD_CLAMP_NONE : 0.0f;
  info.unnormalizedCoordinates = VK_FALSE;
  check(vkCreateSampler(device_, &info, nullptr, &sampler_), "vkCreateSampler");
}

LutSampler::~LutSampler() {
  vkDestroySampler(device_, sampler_, nullptr);
}

}  // namespace matc::vulkan
