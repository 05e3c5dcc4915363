// Copies a finished frame (an RGBA8 image in GENERAL layout, written by a
// compute pass) into a just-acquired swapchain image, scaled to fill it, with
// the barriers around it written out: the image leaves UNDEFINED after the
// acquire wait (Presenter::kAcquireWaitStage) and ends in
// COLOR_ATTACHMENT_OPTIMAL, ready for the overlay render pass.
#pragma once
#include <vulkan/vulkan.h>

#include "engine/gpu/image.h"

namespace qlight::ui {

// vkCmdBlitImage converts RGBA8 to the swapchain's channel order (BGRA8 too).
void recordBlitToSwapchain(VkCommandBuffer cmd, const gpu::Image& frame, VkImage swapchainImage,
                           VkExtent2D swapchainExtent, VkFilter filter);

}  // namespace qlight::ui
