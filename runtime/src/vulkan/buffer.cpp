#include "matc/vulkan/buffer.h"

namespace matc::vulkan {

Buffer::Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage)
    : device_(context.device()), size_(size) {
  if (size == 0) throw VulkanError("a Vulkan buffer cannot be empty");
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(device_, &info, nullptr, &buffer_), "vkCreateBuffer");
  try {
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_, buffer_, &requirements);
    memory_ = context.allocate_memory(
        requirements, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    check(vkBindBufferMemory(device_, buffer_, memory_, 0), "vkBindBufferMemory");
    check(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
    std::memset(mapped_, 0, size_);
  } catch (...) {
    this->~Buffer();
    throw;
  }
}

Buffer::~Buffer() {
  if (memory_ != VK_NULL_HANDLE) vkFreeMemory(device_, memory_, nullptr);  // also unmaps
  if (buffer_ != VK_NULL_HANDLE) vkDestroyBuffer(device_, buffer_, nullptr);
  memory_ = VK_NULL_HANDLE;
  buffer_ = VK_NULL_HANDLE;
}

void Buffer::write_bytes(const void* data, std::size_t size) {
  if (size > size_) throw VulkanError("data larger than the Vulkan buffer");
  std::memcpy(mapped_, data, size);
}

void Buffer::read_bytes(void* data, std::size_t size) const {
  if (size > size_) throw VulkanError("read past the end of the Vulkan buffer");
  std::memcpy(data, mapped_, size);
}

}  // namespace matc::vulkan
