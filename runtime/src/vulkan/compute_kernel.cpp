#include "matc/vulkan/compute_kernel.h"

#include "shader_module.h"

namespace matc::vulkan {

ComputeKernel::ComputeKernel(const Context& context, std::span<const std::uint32_t> spirv,
                             std::span<const Binding> bindings, const std::string& entry_point)
    : context_(context), descriptors_(context, bindings, VK_SHADER_STAGE_COMPUTE_BIT) {
  const VkDevice device = context.device();
  const VkDescriptorSetLayout set_layout = descriptors_.layout();
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  check(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout_), "vkCreatePipelineLayout");
  try {
    const ShaderModule module(device, spirv);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module.handle();
    info.stage.pName = entry_point.c_str();
    info.layout = layout_;
    check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
          "vkCreateComputePipelines");
  } catch (...) {
    vkDestroyPipelineLayout(device, layout_, nullptr);
    throw;
  }
}

ComputeKernel::~ComputeKernel() {
  vkDestroyPipeline(context_.device(), pipeline_, nullptr);
  vkDestroyPipelineLayout(context_.device(), layout_, nullptr);
}

void ComputeKernel::dispatch(std::uint32_t groups_x, std::uint32_t groups_y,
                             std::uint32_t groups_z) const {
  context_.submit([&](VkCommandBuffer commands) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    const VkDescriptorSet set = descriptors_.set();
    if (set != VK_NULL_HANDLE) {  // a shader without resources has no set to bind
      vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0,
                              nullptr);
    }
    vkCmdDispatch(commands, groups_x, groups_y, groups_z);
    // Shader writes become visible to the host once the fence signals.
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                         0, 1, &barrier, 0, nullptr, 0, nullptr);
  });
}

}  // namespace matc::vulkan
