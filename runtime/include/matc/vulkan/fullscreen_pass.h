// An off-screen graphics pass: one full-screen triangle (drawn with 3 vertices and no vertex
// buffer) into a width x height RGBA32F target, a fragment shader per pixel, pixels read back.
// What comparison renders and the 720p cost benchmark run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "matc/vulkan/context.h"
#include "matc/vulkan/descriptor_set.h"
#include "matc/vulkan/image.h"

namespace matc::vulkan {

struct FrameTime {
  double wall_ms = 0.0;    // submit to fence, measured on the host
  double device_ms = 0.0;  // between timestamps around the pass; NaN without timestamps
};

class FullscreenPass {
 public:
  // The vertex shader must place a triangle covering the viewport from gl_VertexIndex 0..2;
  // push constants (push_constant_size bytes, a multiple of 4) reach the fragment stage.
  FullscreenPass(const Context& context, std::span<const std::uint32_t> vertex_spirv,
                 std::span<const std::uint32_t> fragment_spirv, std::span<const Binding> bindings,
                 std::uint32_t width, std::uint32_t height, std::uint32_t push_constant_size = 0);
  ~FullscreenPass();
  FullscreenPass(const FullscreenPass&) = delete;
  FullscreenPass& operator=(const FullscreenPass&) = delete;

  // Renders one frame and waits for it. `push_constants` must hold push_constant_size bytes.
  FrameTime draw(std::span<const std::byte> push_constants = {});
  // The last frame: width * height RGBA floats, top row first. Throws before the first draw.
  std::vector<float> read_pixels() const;

  std::uint32_t width() const { return target_.width(); }
  std::uint32_t height() const { return target_.height(); }

 private:
  const Context& context_;
  Image target_;
  DescriptorSet descriptors_;
  std::uint32_t push_constant_size_;
  bool drawn_ = false;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkQueryPool timestamps_ = VK_NULL_HANDLE;
};

}  // namespace matc::vulkan
