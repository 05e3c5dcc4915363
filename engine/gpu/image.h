// 2D images that compute shaders read and write (kept in GENERAL layout), with readback.
#pragma once
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "engine/gpu/context.h"

namespace qlight::gpu {

class Image {
 public:
  Image() = default;
  Image(const Context& ctx, uint32_t width, uint32_t height, VkFormat format,
        const std::string& name, VkImageUsageFlags extraUsage = 0);

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  VkFormat format() const { return format_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  const std::string& name() const { return name_; }
  size_t texelBytes() const;

  // Raw texels, row-major, tightly packed (waits for the GPU).
  std::vector<uint8_t> readBytes(const Context& ctx) const;
  std::vector<float> readFloats(const Context& ctx) const;  // RGBA32F images only
  void uploadBytes(const Context& ctx, const void* data, size_t bytes);

 private:
  Unique<VkImage> image_;
  Unique<VkDeviceMemory> memory_;
  Unique<VkImageView> view_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  uint32_t width_ = 0, height_ = 0;
  std::string name_;
};

}  // namespace qlight::gpu
