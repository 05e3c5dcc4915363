// A PNG of what the window shows, the image with the panel and the views drawn over it (F12
// and --screenshot-at-exit write the render alone): the presented swapchain image is copied
// to a host buffer in the frame's own command buffer and written out after its fence.
#pragma once
#include <vulkan/vulkan.h>

#include <filesystem>
#include <memory>

#include "engine/gpu/buffer.h"

namespace qlight::ui {

class WindowCapture {
 public:
  explicit WindowCapture(const gpu::Context& ctx) : ctx_(ctx) {}

  // After the overlay pass, the image in PRESENT_SRC layout (and back in it afterwards).
  // The swapchain must have been made with VK_IMAGE_USAGE_TRANSFER_SRC_BIT.
  void record(VkCommandBuffer cmd, VkImage image, VkExtent2D extent, VkFormat format);
  // After the recorded frame's fence: writes the copy as an RGB PNG. False when no copy
  // was recorded since the last write.
  bool write(const std::filesystem::path& path);

 private:
  const gpu::Context& ctx_;
  std::unique_ptr<gpu::Buffer> buffer_;
  VkExtent2D extent_{};
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  bool recorded_ = false;
};

}  // namespace qlight::ui
