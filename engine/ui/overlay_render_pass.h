// The render pass that draws overlays (ImGui) on top of a swapchain image that
// already holds the frame: loadOp LOAD from COLOR_ATTACHMENT_OPTIMAL, ending
// in PRESENT_SRC_KHR.
#pragma once
#include <vulkan/vulkan.h>

#include "engine/gpu/context.h"

namespace qlight::ui {

gpu::Unique<VkRenderPass> createOverlayRenderPass(const gpu::Context& ctx, VkFormat format);

gpu::Unique<VkFramebuffer> createFramebuffer(const gpu::Context& ctx, VkRenderPass pass,
                                             VkImageView view, VkExtent2D extent);

}  // namespace qlight::ui
