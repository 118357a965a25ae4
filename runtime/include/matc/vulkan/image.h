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
  // A texture with a mip chain: levels[k] holds level k (max(1, width >> k) x max(1, height >> k)
  // RGBA floats), as `matc bake` computes them.
  Image(const Context& context, std::uint32_t width, std::uint32_t height,
        std::span<const std::span<const float>> levels);

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  std::uint32_t mip_levels() const { return mip_levels_; }

 private:
  Image(const Context& context, std::uint32_t width, std::uint32_t height, ImageUse use,
        std::uint32_t mip_levels);
  void upload(const Context& context, std::span<const std::span<const float>> levels);

  VkDevice device_;
  std::uint32_t width_;
  std::uint32_t height_;
  std::uint32_t mip_levels_ = 1;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

// Records a layout transition of a colour image's first `mip_levels` levels.
void transition_image(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                      VkPipelineStageFlags source_stage, VkAccessFlags source_access,
                      VkPipelineStageFlags destination_stage, VkAccessFlags destination_access,
                      std::uint32_t mip_levels = 1);

}  // namespace matc::vulkan
