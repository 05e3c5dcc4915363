// Presents frames into a window: owns the swapchain (rebuilt on resize, a vsync change,
// VK_ERROR_OUT_OF_DATE_KHR or VK_SUBOPTIMAL_KHR, skipped while minimized), the
// overlay render pass and its framebuffers, and per frame in flight a command
// buffer, a fence and an acquire semaphore.
//
// Contract for the recorded frame: the first command that touches the
// swapchain image is a barrier whose srcStageMask includes kAcquireWaitStage
// (the submission waits for the acquire there), moving it out of UNDEFINED;
// the frame ends with the overlay render pass, which leaves it in PRESENT_SRC_KHR.
#pragma once
#include <vulkan/vulkan.h>

#include <memory>
#include <optional>
#include <vector>

#include "engine/gpu/context.h"
#include "engine/ui/glfw_window.h"
#include "engine/ui/swapchain.h"

namespace qlight::ui {

struct PresentTarget {
  VkCommandBuffer cmd = VK_NULL_HANDLE;  // begun; record the frame into it
  uint32_t imageIndex = 0;
  VkImage image = VK_NULL_HANDLE;
  VkExtent2D extent{};
  VkFramebuffer framebuffer = VK_NULL_HANDLE;  // of overlayRenderPass() over the image
};

class Presenter {
 public:
  static constexpr VkPipelineStageFlags2 kAcquireWaitStage = VK_PIPELINE_STAGE_2_BLIT_BIT;

  // One frame in flight keeps single-buffered per-frame state (uniforms,
  // counters, scene buffers) safe to rewrite once beginFrame() returns. `vsync`: FIFO
  // presentation (see Swapchain).
  Presenter(const gpu::Context& ctx, const GlfwWindow& window, bool vsync = false,
            uint32_t framesInFlight = 1);
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;
  ~Presenter();

  // Waits until this slot's previous frame finished on the GPU, acquires an
  // image and begins the command buffer. nullopt while the window has no area.
  std::optional<PresentTarget> beginFrame();
  // Ends the command buffer, submits it and presents the image.
  void endFrame(const PresentTarget& target);
  // A change rebuilds the swapchain at the next beginFrame().
  void setVsync(bool vsync);
  bool vsync() const { return vsync_; }

  VkRenderPass overlayRenderPass() const { return renderPass_; }
  const Swapchain& swapchain() const { return *swapchain_; }
  uint32_t framesInFlight() const { return uint32_t(slots_.size()); }
  uint32_t recreations() const { return recreations_; }

 private:
  struct FrameSlot {
    gpu::Unique<VkCommandPool> pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;  // freed with the pool
    gpu::Unique<VkFence> done;
    gpu::Unique<VkSemaphore> acquired;
  };
  bool recreate(WindowExtent extent);  // false: the surface has no area now

  const gpu::Context& ctx_;
  const GlfwWindow& window_;
  std::vector<FrameSlot> slots_;
  uint32_t slot_ = 0;
  std::unique_ptr<Swapchain> swapchain_;
  WindowExtent builtFor_;
  bool vsync_ = false;
  bool recreatePending_ = true;
  uint32_t recreations_ = 0;
  gpu::Unique<VkRenderPass> renderPass_;
  VkFormat renderPassFormat_ = VK_FORMAT_UNDEFINED;
  std::vector<gpu::Unique<VkFramebuffer>> framebuffers_;  // per swapchain image
  std::vector<gpu::Unique<VkSemaphore>> renderFinished_;  // per swapchain image
};

}  // namespace qlight::ui
