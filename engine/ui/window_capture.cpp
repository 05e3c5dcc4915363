#include "engine/ui/window_capture.h"

#include <stb/stb_image_write.h>

#include <stdexcept>
#include <vector>

#include "engine/gpu/barrier.h"

namespace qlight::ui {
namespace {

bool bgra(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_UNORM || f == VK_FORMAT_B8G8R8A8_SRGB; }
bool rgba(VkFormat f) { return f == VK_FORMAT_R8G8B8A8_UNORM || f == VK_FORMAT_R8G8B8A8_SRGB; }

}  // namespace

void WindowCapture::record(VkCommandBuffer cmd, VkImage image, VkExtent2D extent, VkFormat format) {
  if (!bgra(format) && !rgba(format))
    throw std::runtime_error("window capture: the swapchain's format is not 8-bit RGBA or BGRA");
  const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
  if (!buffer_ || buffer_->size() < bytes)
    buffer_ = std::make_unique<gpu::Buffer>(ctx_, bytes, "window.capture", 0,
                                            gpu::MemoryUse::HostVisible);
  gpu::imageLayoutBarrier(
      cmd, image, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
      VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer_->handle(), 1,
                         &region);
  // Presentation reads the image after the queue's semaphore; no access to make visible.
  gpu::imageLayoutBarrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                          VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT,
                          VK_ACCESS_2_NONE);
  extent_ = extent;
  format_ = format;
  recorded_ = true;
}

bool WindowCapture::write(const std::filesystem::path& path) {
  if (!recorded_) return false;
  recorded_ = false;
  const auto* src = static_cast<const uint8_t*>(buffer_->mapped());
  const size_t pixels = size_t(extent_.width) * extent_.height;
  std::vector<uint8_t> rgb(pixels * 3);
  const bool swap = bgra(format_);
  for (size_t i = 0; i < pixels; ++i) {
    rgb[3 * i + 0] = src[4 * i + (swap ? 2 : 0)];
    rgb[3 * i + 1] = src[4 * i + 1];
    rgb[3 * i + 2] = src[4 * i + (swap ? 0 : 2)];
  }
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  if (!stbi_write_png(path.string().c_str(), int(extent_.width), int(extent_.height), 3, rgb.data(),
                      int(extent_.width) * 3))
    throw std::runtime_error("cannot write " + path.string());
  return true;
}

}  // namespace qlight::ui
