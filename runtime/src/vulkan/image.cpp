#include "matc/vulkan/image.h"

#include <algorithm>
#include <string>
#include <vector>

#include "matc/vulkan/buffer.h"

namespace matc::vulkan {

void transition_image(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                      VkPipelineStageFlags source_stage, VkAccessFlags source_access,
                      VkPipelineStageFlags destination_stage, VkAccessFlags destination_access,
                      std::uint32_t mip_levels) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = source_access;
  barrier.dstAccessMask = destination_access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, mip_levels, 0, 1};
  vkCmdPipelineBarrier(commands, source_stage, destination_stage, 0, 0, nullptr, 0, nullptr, 1,
                       &barrier);
}

Image::Image(const Context& context, std::uint32_t width, std::uint32_t height, ImageUse use)
    : Image(context, width, height, use, 1) {}

Image::Image(const Context& context, std::uint32_t width, std::uint32_t height, ImageUse use,
             std::uint32_t mip_levels)
    : device_(context.device()), width_(width), height_(height), mip_levels_(mip_levels) {
  VkFormatProperties format_properties;
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), kFormat, &format_properties);
  const VkFormatFeatureFlags needed = use == ImageUse::texture
                                          ? VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT
                                          : VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
  if ((format_properties.optimalTilingFeatures & needed) != needed) {
    throw VulkanError(context.device_name() + (use == ImageUse::texture
                                                   ? " cannot filter RGBA32F textures linearly"
                                                   : " cannot render to RGBA32F images"));
  }
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = kFormat;
  info.extent = {width, height, 1};
  info.mipLevels = mip_levels_;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = use == ImageUse::texture
                   ? VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT
                   : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(vkCreateImage(device_, &info, nullptr, &image_), "vkCreateImage");
  try {
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device_, image_, &requirements);
    memory_ = context.allocate_memory(requirements, 0);
    check(vkBindImageMemory(device_, image_, memory_, 0), "vkBindImageMemory");
    VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view_info.image = image_;
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = kFormat;
    view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, mip_levels_, 0, 1};
    check(vkCreateImageView(device_, &view_info, nullptr, &view_), "vkCreateImageView");
  } catch (...) {
    this->~Image();
    throw;
  }
}

Image::~Image() {
  if (view_ != VK_NULL_HANDLE) vkDestroyImageView(device_, view_, nullptr);
  if (image_ != VK_NULL_HANDLE) vkDestroyImage(device_, image_, nullptr);
  if (memory_ != VK_NULL_HANDLE) vkFreeMemory(device_, memory_, nullptr);
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
}

Image::Image(const Context& context, std::uint32_t width, std::uint32_t height,
             std::span<const float> texels)
    : Image(context, width, height, ImageUse::texture) {
  const std::span<const float> level[] = {texels};
  upload(context, level);
}

Image::Image(const Context& context, std::uint32_t width, std::uint32_t height,
             std::span<const std::span<const float>> levels)
    : Image(context, width, height, ImageUse::texture, static_cast<std::uint32_t>(levels.size())) {
  upload(context, levels);
}

void Image::upload(const Context& context, std::span<const std::span<const float>> levels) {
  std::vector<float> staged;
  std::vector<VkBufferImageCopy> regions;
  for (std::uint32_t k = 0; k < levels.size(); ++k) {
    const std::uint32_t width = std::max(1u, width_ >> k), height = std::max(1u, height_ >> k);
    const std::size_t expected = std::size_t{width} * height * 4;
    if (levels[k].size() != expected) {
      throw VulkanError("texture level " + std::to_string(k) + " has " +
                        std::to_string(levels[k].size()) + " floats, expected " +
                        std::to_string(expected));
    }
    VkBufferImageCopy region{};
    region.bufferOffset = staged.size() * sizeof(float);
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, k, 0, 1};
    region.imageExtent = {width, height, 1};
    regions.push_back(region);
    staged.insert(staged.end(), levels[k].begin(), levels[k].end());
  }
  Buffer staging(context, staged.size() * sizeof(float), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  staging.write<float>(staged);
  context.submit([&](VkCommandBuffer commands) {
    transition_image(commands, image_, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, mip_levels_);
    vkCmdCopyBufferToImage(commands, staging.handle(), image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           static_cast<std::uint32_t>(regions.size()), regions.data());
    transition_image(commands, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                     VK_ACCESS_SHADER_READ_BIT, mip_levels_);
  });
}

}  // namespace matc::vulkan
