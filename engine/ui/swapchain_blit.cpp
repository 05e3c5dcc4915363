#include "engine/ui/swapchain_blit.h"

#include "engine/ui/presenter.h"

namespace qlight::ui {
namespace {

constexpr VkImageSubresourceRange kColor{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};

VkImageMemoryBarrier2 imageBarrier(VkImage image, VkImageLayout from, VkImageLayout to) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = kColor;
  return b;
}

void barriers(VkCommandBuffer cmd, const VkImageMemoryBarrier2* b, uint32_t count) {
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = count;
  dep.pImageMemoryBarriers = b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace

void recordBlitToSwapchain(VkCommandBuffer cmd, const gpu::Image& frame, VkImage swapchainImage,
                           VkExtent2D swapchainExtent, VkFilter filter) {
  VkImageMemoryBarrier2 before[2];
  // The swapchain image: after the acquire (the submission waits at this
  // stage), old contents discarded.
  before[0] =
      imageBarrier(swapchainImage, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  before[0].srcStageMask = Presenter::kAcquireWaitStage;
  before[0].srcAccessMask = VK_ACCESS_2_NONE;
  before[0].dstStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  before[0].dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  // The frame: the compute pass's stores become visible to the blit's reads.
  before[1] = imageBarrier(frame.handle(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL);
  before[1].srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  before[1].srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  before[1].dstStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  before[1].dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
  barriers(cmd, before, 2);

  VkImageBlit region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = {int32_t(frame.width()), int32_t(frame.height()), 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstOffsets[1] = {int32_t(swapchainExtent.width), int32_t(swapchainExtent.height), 1};
  vkCmdBlitImage(cmd, frame.handle(), VK_IMAGE_LAYOUT_GENERAL, swapchainImage,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, filter);

  VkImageMemoryBarrier2 after[2];
  // The swapchain image: blit writes before the overlay pass loads and draws.
  after[0] = imageBarrier(swapchainImage, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  after[0].srcStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  after[0].srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  after[0].dstStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  after[0].dstAccessMask =
      VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  // The frame: the next frame's compute or transfer writes wait for this read (WAR).
  after[1] = imageBarrier(frame.handle(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL);
  after[1].srcStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  after[1].srcAccessMask = VK_ACCESS_2_NONE;
  after[1].dstStageMask =
      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  after[1].dstAccessMask = VK_ACCESS_2_NONE;
  barriers(cmd, after, 2);
}

}  // namespace qlight::ui
