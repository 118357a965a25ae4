// The resources a shader reads and writes, bound in descriptor set 0 by binding number.
#pragma once

#include <cstdint>
#include <span>

#include "matc/vulkan/buffer.h"
#include "matc/vulkan/context.h"
#include "matc/vulkan/image.h"
#include "matc/vulkan/sampler.h"

namespace matc::vulkan {

struct Binding {
  std::uint32_t index = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const Buffer* buffer = nullptr;
  VkImageView image_view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;

  static Binding storage_buffer(std::uint32_t index, const Buffer& buffer) {
    return {index, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &buffer};
  }
  static Binding uniform_buffer(std::uint32_t index, const Buffer& buffer) {
    return {index, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &buffer};
  }
  static Binding sampled_image(std::uint32_t index, const Image& image) {
    return {index, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, nullptr, image.view()};
  }
  static Binding separate_sampler(std::uint32_t index, const LutSampler& sampler) {
    return {index, VK_DESCRIPTOR_TYPE_SAMPLER, nullptr, VK_NULL_HANDLE, sampler.handle()};
  }
};

// A layout, a pool and one set, written once with `bindings`, visible to `stages`.
class DescriptorSet {
 public:
  DescriptorSet(const Context& context, std::span<const Binding> bindings,
                VkShaderStageFlags stages);
  ~DescriptorSet();
  DescriptorSet(const DescriptorSet&) = delete;
  DescriptorSet& operator=(const DescriptorSet&) = delete;

  VkDescriptorSetLayout layout() const { return layout_; }
  VkDescriptorSet set() const { return set_; }

 private:
  VkDevice device_;
  VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace matc::vulkan
