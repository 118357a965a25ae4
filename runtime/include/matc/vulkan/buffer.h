// A buffer in host-visible, coherent memory, mapped for its whole life: queries go in and results
// come out through plain memcpy, with no staging copies (lavapipe's memory is all host memory).
#pragma once

#include <cstddef>
#include <cstring>
#include <span>
#include <vector>

#include "matc/vulkan/context.h"

namespace matc::vulkan {

class Buffer {
 public:
  Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage);
  ~Buffer();
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  std::span<std::byte> bytes() { return {static_cast<std::byte*>(mapped_), size_}; }
  std::span<const std::byte> bytes() const {
    return {static_cast<const std::byte*>(mapped_), size_};
  }

  // Copies `values` to the start of the buffer (throws VulkanError if they do not fit).
  template <typename T>
  void write(std::span<const T> values) {
    write_bytes(values.data(), values.size_bytes());
  }
  // The buffer's first `count` elements.
  template <typename T>
  std::vector<T> read(std::size_t count) const {
    std::vector<T> values(count);
    read_bytes(values.data(), count * sizeof(T));
    return values;
  }

 private:
  void write_bytes(const void* data, std::size_t size);
  void read_bytes(void* data, std::size_t size) const;

  VkDevice device_;
  VkDeviceSize size_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
};

}  // namespace matc::vulkan
