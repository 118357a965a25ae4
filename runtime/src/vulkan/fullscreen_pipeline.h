// The render pass and pipeline of a full-screen pass (one triangle, one RGBA32F target): shared by
// FullscreenPass, which draws with them, and the pipeline statistics, which only compile them.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

namespace matc::vulkan {

// One RGBA32F colour attachment, cleared, left ready for a copy to the host.
VkRenderPass create_fullscreen_render_pass(VkDevice device);

// A triangle list without vertex input, the whole width x height viewport, no blending.
VkPipeline create_fullscreen_pipeline(VkDevice device, VkRenderPass render_pass,
                                      VkPipelineLayout layout, VkShaderModule vertex,
                                      VkShaderModule fragment, std::uint32_t width,
                                      std::uint32_t height, VkPipelineCreateFlags flags = 0);

}  // namespace matc::vulkan
