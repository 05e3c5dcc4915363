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
  // `wanted` is the window's framebuffer size (used when the surface leaves it
  // to us); it must be non-zero. Throws std::runtime_error naming the problem
  // (no surface, no blit-capable format, creation failure).
  Swapchain(const gpu::Context& ctx, VkExtent2D wanted, VkSwapchainKHR old = VK_NULL_HANDLE);

  VkSwapchainKHR handle() const { return swapchain_; }
  VkFormat format() const { return format_; }
  // The swapchain's format stores sRGB-encoded values when written linear ones.
  bool encodesSrgb() const;
  VkExtent2D extent() const { return extent_; }
  uint32_t imageCount() const { return uint32_t(images_.size()); }
  uint32_t minImageCount() const { return minImageCount_; }
  VkImage image(uint32_t i) const { return images_[i]; }
  VkImageView view(uint32_t i) const { return views_[i]; }

 private:
  gpu::Unique<VkSwapchainKHR> swapchain_;
  std::vector<VkImage> images_;  // owned by the swapchain
  std::vector<gpu::Unique<VkImageView>> views_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  uint32_t minImageCount_ = 2;
};

}  // namespace qlight::ui
