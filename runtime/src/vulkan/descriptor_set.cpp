#include "matc/vulkan/descriptor_set.h"

#include <vector>

namespace matc::vulkan {

DescriptorSet::DescriptorSet(const Context& context, std::span<const Binding> bindings,
                             VkShaderStageFlags stages)
    : device_(context.device()) {
  std::vector<VkDescriptorSetLayoutBinding> layout_bindings;
  std::vector<VkDescriptorPoolSize> pool_sizes;
  for (const Binding& binding : bindings) {
    layout_bindings.push_back({binding.index, binding.type, 1, stages, nullptr});
    pool_sizes.push_back({binding.type, 1});
  }
  try {
    VkDescriptorSetLayoutCreateInfo layout_info{
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layout_info.bindingCount = static_cast<std::uint32_t>(layout_bindings.size());
    layout_info.pBindings = layout_bindings.data();
    check(vkCreateDescriptorSetLayout(device_, &layout_info, nullptr, &layout_),
          "vkCreateDescriptorSetLayout");
    if (bindings.empty()) return;

    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = static_cast<std::uint32_t>(pool_sizes.size());
    pool_info.pPoolSizes = pool_sizes.data();
    check(vkCreateDescriptorPool(device_, &pool_info, nullptr, &pool_), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = pool_;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &layout_;
    check(vkAllocateDescriptorSets(device_, &allocate, &set_), "vkAllocateDescriptorSets");

    // Reserved up front: the writes point into these vectors.
    std::vector<VkDescriptorBufferInfo> buffer_infos;
    std::vector<VkDescriptorImageInfo> image_infos;
    buffer_infos.reserve(bindings.size());
    image_infos.reserve(bindings.size());
    std::vector<VkWriteDescriptorSet> writes;
    for (const Binding& binding : bindings) {
      VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      write.dstSet = set_;
      write.dstBinding = binding.index;
      write.descriptorCount = 1;
      write.descriptorType = binding.type;
      if (binding.buffer != nullptr) {
        buffer_infos.push_back({binding.buffer->handle(), 0, VK_WHOLE_SIZE});
        write.pBufferInfo = &buffer_infos.back();
      } else {
        image_infos.push_back({binding.sampler, binding.image_view,
                               binding.image_view != VK_NULL_HANDLE
                                   ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                   : VK_IMAGE_LAYOUT_UNDEFINED});
        write.pImageInfo = &image_infos.back();
      }
      writes.push_back(write);
    }
    vkUpdateDescriptorSets(device_, static_cast<std::uint32_t>(writes.size()), writes.data(), 0,
                           nullptr);
  } catch (...) {
    this->~DescriptorSet();
    throw;
  }
}

DescriptorSet::~DescriptorSet() {
  if (pool_ != VK_NULL_HANDLE) vkDestroyDescriptorPool(device_, pool_, nullptr);
  if (layout_ != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(device_, layout_, nullptr);
  pool_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
}

}  // namespace matc::vulkan
