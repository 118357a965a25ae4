// A 2D RGBA32F image with optimal tiling: either a texture the shaders sample with linear
// filtering (the LUT), or a colour target a fragment pass renders into.
#pragma once

#include <cstdint>
#include <span>

#include "matc/vulkan/context.h"

namespace matc::vulkan {

enum class ImageUse {
  texture,       // uploaded once, then SHADER_READ_ONLY_OPTIMAL
  color_target,  // rendered into, then copied out (TRANSFER_SRC)
};

class Image {
 public:
  static constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

  // Throws VulkanError when the device cannot filter (texture) or render to (color_target) kFormat.
  Image(const Context& context, std::uint32_t width, std::uint32_t height, ImageUse use);
  ~Image();
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  // A texture holding `texels` (width * height RGBA floats, rows first), ready to sample.
  Image(const Context& context, std::uint32_t width, std::uint32_t height,
        std::span<const float> texels);

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }

 private:
  void upload(const Context& context, std::span<const float> texels);

  VkDevice device_;
  std::uint32_t width_;
  std::uint32_t height_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

// Records a layout transition of a single-level colour image.
void transition_image(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                      VkPipelineStageFlags source_stage, VkAccessFlags source_access,
                      VkPipelineStageFlags destination_stage, VkAccessFlags destination_access);

}  // namespace matc::vulkan
