// A VkShaderModule for the life of a pipeline's construction.
#pragma once

#include <cstdint>
#include <span>

#include "matc/vulkan/context.h"

namespace matc::vulkan {

class ShaderModule {
 public:
  ShaderModule(VkDevice device, std::span<const std::uint32_t> words) : device_(device) {
    if (words.empty()) throw VulkanError("empty SPIR-V module");
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = words.size_bytes();
    info.pCode = words.data();
    check(vkCreateShaderModule(device_, &info, nullptr, &module_), "vkCreateShaderModule");
  }
  ~ShaderModule() { vkDestroyShaderModule(device_, module_, nullptr); }
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;

  VkShaderModule handle() const { return module_; }

 private:
  VkDevice device_;
  VkShaderModule module_ = VK_NULL_HANDLE;
};

}  // namespace matc::vulkan
