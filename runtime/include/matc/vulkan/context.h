// A Vulkan instance, one device and one queue: what matc needs to run its shaders off screen
// (compute dispatches and full-screen fragment passes), on Mesa's lavapipe or on a GPU.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace matc::vulkan {

// Any Vulkan failure, with what was being done and the VkResult's name.
class VulkanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// No Vulkan 1.1 device with a graphics and compute queue (or none matching the requested name).
class NoDeviceError : public VulkanError {
 public:
  using VulkanError::VulkanError;
};

// Throws VulkanError("<what>: VK_ERROR_...") unless result is VK_SUCCESS.
void check(VkResult result, const char* what);
const char* result_name(VkResult result);

struct ContextOptions {
  // Enables VK_LAYER_KHRONOS_validation and collects every warning and error it reports.
  bool validation = false;
  // Picks the first device whose name contains this (e.g. "llvmpipe"); empty: prefer a discrete
  // GPU, then an integrated one, then anything else.
  std::string device_name;
  // Enables VK_KHR_pipeline_executable_properties, so that pipeline_statistics.h can read the
  // shader compiler's statistics (RADV and other drivers that have it; lavapipe does not).
  bool pipeline_statistics = false;
};

class Context {
 public:
  explicit Context(const ContextOptions& options = {});
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkDevice device() const;
  VkPhysicalDevice physical_device() const;
  const VkPhysicalDeviceProperties& properties() const;
  std::string device_name() const;
  // Whether the queue writes timestamps (vkCmdWriteTimestamp) that can be converted to time.
  bool has_timestamps() const;

  // A memory type allowed by type_bits with all of `flags`; throws VulkanError if none.
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const;
  // Device memory meeting `requirements` with all of `flags`; the caller frees it.
  VkDeviceMemory allocate_memory(const VkMemoryRequirements& requirements,
                                 VkMemoryPropertyFlags flags) const;

  // Records commands into a one-time command buffer, submits it and waits for it to finish.
  void submit(const std::function<void(VkCommandBuffer)>& record) const;

  // The validation layer's warnings and errors so far (empty without ContextOptions::validation).
  std::vector<std::string> validation_messages() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace matc::vulkan
