#include "matc/vulkan/fullscreen_pass.h"

#include <array>
#include <chrono>
#include <limits>

#include "fullscreen_pipeline.h"
#include "matc/vulkan/buffer.h"
#include "shader_module.h"

namespace matc::vulkan {

FullscreenPass::FullscreenPass(const Context& context, std::span<const std::uint32_t> vertex_spirv,
                               std::span<const std::uint32_t> fragment_spirv,
                               std::span<const Binding> bindings, std::uint32_t width,
                               std::uint32_t height, std::uint32_t push_constant_size)
    : context_(context),
      target_(context, width, height, ImageUse::color_target),
      descriptors_(context, bindings, VK_SHADER_STAGE_FRAGMENT_BIT),
      push_constant_size_(push_constant_size) {
  if (push_constant_size % 4 != 0 ||
      push_constant_size > context.properties().limits.maxPushConstantsSize) {
    throw VulkanError("push constants must be a multiple of 4 bytes within the device's limit");
  }
  const VkDevice device = context.device();
  try {
    render_pass_ = create_fullscreen_render_pass(device);
    const VkImageView view = target_.view();
    VkFramebufferCreateInfo framebuffer_info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    framebuffer_info.renderPass = render_pass_;
    framebuffer_info.attachmentCount = 1;
    framebuffer_info.pAttachments = &view;
    framebuffer_info.width = width;
    framebuffer_info.height = height;
    framebuffer_info.layers = 1;
    check(vkCreateFramebuffer(device, &framebuffer_info, nullptr, &framebuffer_),
          "vkCreateFramebuffer");

    const VkDescriptorSetLayout set_layout = descriptors_.layout();
    const VkPushConstantRange range{VK_SHADER_STAGE_FRAGMENT_BIT, 0, push_constant_size};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout;
    layout_info.pushConstantRangeCount = push_constant_size > 0 ? 1 : 0;
    layout_info.pPushConstantRanges = &range;
    check(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout_),
          "vkCreatePipelineLayout");
    const ShaderModule vertex(device, vertex_spirv);
    const ShaderModule fragment(device, fragment_spirv);
    pipeline_ = create_fullscreen_pipeline(device, render_pass_, layout_, vertex.handle(),
                                           fragment.handle(), width, height);
    if (context.has_timestamps()) {
      VkQueryPoolCreateInfo query_info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
      query_info.queryType = VK_QUERY_TYPE_TIMESTAMP;
      query_info.queryCount = 2;
      check(vkCreateQueryPool(device, &query_info, nullptr, &timestamps_), "vkCreateQueryPool");
    }
  } catch (...) {
    this->~FullscreenPass();
    throw;
  }
}

FullscreenPass::~FullscreenPass() {
  const VkDevice device = context_.device();
  if (timestamps_ != VK_NULL_HANDLE) vkDestroyQueryPool(device, timestamps_, nullptr);
  if (pipeline_ != VK_NULL_HANDLE) vkDestroyPipeline(device, pipeline_, nullptr);
  if (layout_ != VK_NULL_HANDLE) vkDestroyPipelineLayout(device, layout_, nullptr);
  if (framebuffer_ != VK_NULL_HANDLE) vkDestroyFramebuffer(device, framebuffer_, nullptr);
  if (render_pass_ != VK_NULL_HANDLE) vkDestroyRenderPass(device, render_pass_, nullptr);
  timestamps_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  framebuffer_ = VK_NULL_HANDLE;
  render_pass_ = VK_NULL_HANDLE;
}

FrameTime FullscreenPass::draw(std::span<const std::byte> push_constants) {
  if (push_constants.size() != push_constant_size_) {
    throw VulkanError("draw() needs " + std::to_string(push_constant_size_) +
                      " bytes of push constants, got " + std::to_string(push_constants.size()));
  }
  const auto start = std::chrono::steady_clock::now();
  context_.submit([&](VkCommandBuffer commands) {
    if (timestamps_ != VK_NULL_HANDLE) {
      vkCmdResetQueryPool(commands, timestamps_, 0, 2);
      vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps_, 0);
    }
    VkClearValue clear{};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = render_pass_;
    begin.framebuffer = framebuffer_;
    begin.renderArea = {{0, 0}, {target_.width(), target_.height()}};
    begin.clearValueCount = 1;
    begin.pClearValues = &clear;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    const VkDescriptorSet set = descriptors_.set();
    if (set != VK_NULL_HANDLE) {  // a shader without resources has no set to bind
      vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set, 0,
                              nullptr);
    }
    if (push_constant_size_ > 0) {
      vkCmdPushConstants(commands, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, push_constant_size_,
                         push_constants.data());
    }
    vkCmdDraw(commands, 3, 1, 0, 0);
    vkCmdEndRenderPass(commands);
    if (timestamps_ != VK_NULL_HANDLE)
      vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, 1);
  });
  FrameTime time;
  time.wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  time.device_ms = std::numeric_limits<double>::quiet_NaN();
  if (timestamps_ != VK_NULL_HANDLE) {
    std::array<std::uint64_t, 2> ticks{};
    check(vkGetQueryPoolResults(context_.device(), timestamps_, 0, 2, sizeof(ticks), ticks.data(),
                                sizeof(std::uint64_t),
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
    time.device_ms = static_cast<double>(ticks[1] - ticks[0]) *
                     context_.properties().limits.timestampPeriod * 1e-6;
  }
  drawn_ = true;
  return time;
}

std::vector<float> FullscreenPass::read_pixels() const {
  if (!drawn_) throw VulkanError("read_pixels() before the first draw()");
  const std::size_t count = std::size_t{target_.width()} * target_.height() * 4;
  Buffer readback(context_, count * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  context_.submit([&](VkCommandBuffer commands) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {target_.width(), target_.height(), 1};
    vkCmdCopyImageToBuffer(commands, target_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback.handle(), 1, &region);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
  });
  return readback.read<float>(count);
}

}  // namespace matc::vulkan
