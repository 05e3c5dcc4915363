#include "engine/ui/swapchain.h"

#include <algorithm>
#include <stdexcept>

#include "engine/gpu/vk_check.h"

namespace qlight::ui {
namespace {

bool canBlitTo(VkPhysicalDevice gpu, VkFormat format) {
  VkFormatProperties props;
  vkGetPhysicalDeviceFormatProperties(gpu, format, &props);
  return props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT;
}

// The display pass writes sRGB-encoded RGBA8, so a UNORM target shows it
// unchanged (ImGui also expects UNORM); an sRGB target is the fallback.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice gpu, VkSurfaceKHR surface) {
  uint32_t count = 0;
  QL_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  QL_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, formats.data()));
  const VkFormat preferred[] = {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM,
                                VK_FORMAT_A2B10G10R10_UNORM_PACK32, VK_FORMAT_B8G8R8A8_SRGB,
                                VK_FORMAT_R8G8B8A8_SRGB};
  for (VkFormat want : preferred)
    for (const VkSurfaceFormatKHR& f : formats)
      if (f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR &&
          canBlitTo(gpu, f.format))
        return f;
  for (const VkSurfaceFormatKHR& f : formats)
    if (canBlitTo(gpu, f.format)) return f;
  throw std::runtime_error("swapchain: the surface offers no format that can be a blit target");
}

// Without vsync the path tracer gets every frame it can make: no waiting for vertical blank.
VkPresentModeKHR choosePresentMode(VkPhysicalDevice gpu, VkSurfaceKHR surface, bool vsync) {
  if (vsync) return VK_PRESENT_MODE_FIFO_KHR;  // always supported
  uint32_t count = 0;
  QL_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  QL_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, modes.data()));
  for (VkPresentModeKHR want : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), want) != modes.end()) return want;
  return VK_PRESENT_MODE_FIFO_KHR;  // always supported
}

}  // namespace

VkExtent2D Swapchain::extentFor(const VkSurfaceCapabilitiesKHR& caps, VkExtent2D wanted) {
  if (caps.currentExtent.width != UINT32_MAX) return caps.currentExtent;
  return {std::clamp(wanted.width, caps.minImageExtent.width, caps.maxImageExtent.width),
          std::clamp(wanted.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
}

Swapchain::Swapchain(const gpu::Context& ctx, const VkSurfaceCapabilitiesKHR& caps,
                     VkExtent2D wanted, bool vsync, VkSwapchainKHR old) {
  VkSurfaceKHR surface = ctx.surface();
  VkPhysicalDevice gpu = ctx.physicalDevice();
  VkDevice device = ctx.device();
  if (!surface) throw std::runtime_error("swapchain: the context was created without a surface");
  VkBool32 supported = VK_FALSE;
  QL_VK(vkGetPhysicalDeviceSurfaceSupportKHR(gpu, ctx.queueFamily(), surface, &supported));
  if (!supported)
    throw std::runtime_error("swapchain: the queue family cannot present to the window");

  const VkImageUsageFlags usage =
      VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if ((caps.supportedUsageFlags & usage) != usage)
    throw std::runtime_error("swapchain: surface images cannot be blit targets and attachments");
  // Copies out for window captures (ui/window_capture.h), where the surface allows them.
  const VkImageUsageFlags capture = caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  extent_ = extentFor(caps, wanted);
  if (extent_.width == 0 || extent_.height == 0)  // the presenter waits instead
    throw std::runtime_error("swapchain: the window has no area (minimized)");

  VkSurfaceFormatKHR surfaceFormat = chooseFormat(gpu, surface);
  format_ = surfaceFormat.format;
  // ImGui's Vulkan backend needs at least two images.
  uint32_t count = std::max(2u, caps.minImageCount + 1);
  if (caps.maxImageCount) count = std::min(count, caps.maxImageCount);
  minImageCount_ = count;

  VkCompositeAlphaFlagBitsKHR alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(caps.supportedCompositeAlpha & alpha))
    alpha = VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                        -int32_t(caps.supportedCompositeAlpha));  // lowest bit

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = count;
  info.imageFormat = surfaceFormat.format;
  info.imageColorSpace = surfaceFormat.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = usage | capture;
  copyable_ = capture != 0;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = alpha;
  presentMode_ = choosePresentMode(gpu, surface, vsync);
  info.presentMode = presentMode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = old;
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  QL_VK(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain));
  swapchain_ = gpu::Unique<VkSwapchainKHR>(
      swapchain, [device](VkSwapchainKHR s) { vkDestroySwapchainKHR(device, s, nullptr); });

  uint32_t imageCount = 0;
  QL_VK(vkGetSwapchainImagesKHR(device, swapchain, &imageCount, nullptr));
  images_.resize(imageCount);
  QL_VK(vkGetSwapchainImagesKHR(device, swapchain, &imageCount, images_.data()));
  for (uint32_t i = 0; i < imageCount; ++i) {
    ctx.setName(uint64_t(images_[i]), VK_OBJECT_TYPE_IMAGE, "swapchain." + std::to_string(i));
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = images_[i];
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format_;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    QL_VK(vkCreateImageView(device, &viewInfo, nullptr, &view));
    views_.emplace_back(view, [device](VkImageView v) { vkDestroyImageView(device, v, nullptr); });
  }
}

bool Swapchain::encodesSrgb() const {
  return format_ == VK_FORMAT_B8G8R8A8_SRGB || format_ == VK_FORMAT_R8G8B8A8_SRGB ||
         format_ == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
}

}  // namespace qlight::ui
