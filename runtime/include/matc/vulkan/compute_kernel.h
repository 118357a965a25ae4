// A compute pipeline built from a SPIR-V module, dispatched synchronously: when dispatch()
// returns, what the shader wrote to host-visible buffers can be read.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "matc/vulkan/context.h"
#include "matc/vulkan/descriptor_set.h"

namespace matc::vulkan {

class ComputeKernel {
 public:
  ComputeKernel(const Context& context, std::span<const std::uint32_t> spirv,
                std::span<const Binding> bindings, const std::string& entry_point = "main");
  ~ComputeKernel();
  ComputeKernel(const ComputeKernel&) = delete;
  ComputeKernel& operator=(const ComputeKernel&) = delete;

  void dispatch(std::uint32_t groups_x, std::uint32_t groups_y = 1,
                std::uint32_t groups_z = 1) const;

 private:
  const Context& context_;
  DescriptorSet descriptors_;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace matc::vulkan
