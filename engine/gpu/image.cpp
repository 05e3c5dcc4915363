#include "engine/gpu/image.h"

#include <cstring>
#include <stdexcept>

#include "engine/gpu/barrier.h"
#include "engine/gpu/buffer.h"
#include "engine/gpu/vk_check.h"

namespace qlight::gpu {

Image::Image(const Context& ctx, uint32_t width, uint32_t height, VkFormat format,
             const std::string& name, VkImageUsageFlags extraUsage)
    : format_(format), width_(width), height_(height), name_(name) {
  if (width == 0 || height == 0) throw std::invalid_argument("image " + name + " has no texels");
  VkDevice device = ctx.device();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
               VK_IMAGE_USAGE_TRANSFER_DST_BIT | extraUsage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  QL_VK(vkCreateImage(device, &info, nullptr, &image));
  image_ = Unique<VkImage>(image, [device](VkImage i) { vkDestroyImage(device, i, nullptr); });
  ctx.setName(uint64_t(image), VK_OBJECT_TYPE_IMAGE, name);

  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, image, &req);
  memory_ = ctx.allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  QL_VK(vkBindImageMemory(device, image, memory_, 0));

  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = format;
  viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  QL_VK(vkCreateImageView(device, &viewInfo, nullptr, &view));
  view_ = Unique<VkImageView>(view,
                              [device](VkImageView v) { vkDestroyImageView(device, v, nullptr); });

  // Compute passes use GENERAL throughout, so the only layout change is this one.
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    imageLayoutBarrier(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                       VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                       VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                       VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
    VkClearColorValue zero{};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                  VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
  });
}

size_t Image::texelBytes() const {
  switch (format_) {
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return 16;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
      return 8;
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
      return 4;
    default:
      throw std::runtime_error("image " + name_ + ": texel size of this format unknown");
  }
}

namespace {
// Copies between an image in GENERAL layout and a buffer, with the barriers
// that make earlier compute writes visible and the transfer finish first.
void copyImageBuffer(VkCommandBuffer cmd, VkImage image, VkBuffer buffer, uint32_t w, uint32_t h,
                     bool toBuffer) {
  memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COPY_BIT,
                VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {w, h, 1};
  if (toBuffer)
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_GENERAL, buffer, 1, &region);
  else
    vkCmdCopyBufferToImage(cmd, buffer, image, VK_IMAGE_LAYOUT_GENERAL, 1, &region);
  memoryBarrier(
      cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
      VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_2_HOST_BIT,
      VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT | VK_ACCESS_2_HOST_READ_BIT);
}
}  // namespace

std::vector<uint8_t> Image::readBytes(const Context& ctx) const {
  size_t bytes = size_t(width_) * height_ * texelBytes();
  Buffer staging(ctx, bytes, name_ + ".readback", 0, MemoryUse::HostVisible);
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    copyImageBuffer(cmd, image_, staging.handle(), width_, height_, true);
  });
  std::vector<uint8_t> out(bytes);
  std::memcpy(out.data(), staging.mapped(), bytes);
  return out;
}

std::vector<float> Image::readFloats(const Context& ctx) const {
  if (format_ != VK_FORMAT_R32G32B32A32_SFLOAT && format_ != VK_FORMAT_R32_SFLOAT)
    throw std::runtime_error("image " + name_ + " is not a 32-bit float image");
  auto bytes = readBytes(ctx);
  std::vector<float> out(bytes.size() / 4);
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

void Image::uploadBytes(const Context& ctx, const void* data, size_t bytes) {
  if (bytes != size_t(width_) * height_ * texelBytes())
    throw std::runtime_error("image " + name_ + ": upload size does not match the image");
  Buffer staging(ctx, bytes, name_ + ".staging", 0, MemoryUse::HostVisible);
  std::memcpy(staging.mapped(), data, bytes);
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    copyImageBuffer(cmd, image_, staging.handle(), width_, height_, false);
  });
}

}  // namespace qlight::gpu
