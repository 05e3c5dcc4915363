// A VkSwapchainKHR over the context's surface with a view per image. Immutable:
// on resize or VK_ERROR_OUT_OF_DATE_KHR the owner builds a new one, passing
// the old one so the presentation engine can hand images over.
#pragma once
#include <vulkan/vulkan.h>

#include <vector>

#include "engine/gpu/context.h"

namespace qlight::ui {

class Swapchain {
 public:
  // The size a swapchain over a surface with these capabilities gets: the surface's, or
  // `wanted` (the window's framebuffer size) where the surface leaves it to us. Zero in a
  // dimension while the window has no area (minimized): no swapchain can be made then.
  static VkExtent2D extentFor(const VkSurfaceCapabilitiesKHR& caps, VkExtent2D wanted);

  // `caps` are the surface's capabilities now; extentFor(caps, wanted) must be non-zero.
  // `vsync`: FIFO presentation (waits for vertical blank); else MAILBOX or IMMEDIATE where
  // the surface has them. Throws std::runtime_error naming the problem (no surface, no
  // blit-capable format, no area, creation failure).
  Swapchain(const gpu::Context& ctx, const VkSurfaceCapabilitiesKHR& caps, VkExtent2D wanted,
            bool vsync, VkSwapchainKHR old = VK_NULL_HANDLE);

  VkSwapchainKHR handle() const { return swapchain_; }
  VkFormat format() const { return format_; }
  // The images can be copied out (window captures).
  bool copyable() const { return copyable_; }
  // The swapchain's format stores sRGB-encoded values when written linear ones.
  bool encodesSrgb() const;
  VkExtent2D extent() const { return extent_; }
  VkPresentModeKHR presentMode() const { return presentMode_; }
  uint32_t imageCount() const { return uint32_t(images_.size()); }
  uint32_t minImageCount() const { return minImageCount_; }
  VkImage image(uint32_t i) const { return images_[i]; }
  VkImageView view(uint32_t i) const { return views_[i]; }

 private:
  gpu::Unique<VkSwapchainKHR> swapchain_;
  std::vector<VkImage> images_;  // owned by the swapchain
  std::vector<gpu::Unique<VkImageView>> views_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  bool copyable_ = false;
  VkExtent2D extent_{};
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  uint32_t minImageCount_ = 2;
};

}  // namespace qlight::ui
