#include "engine/ui/presenter.h"

#include <stdexcept>

#include "engine/gpu/vk_check.h"
#include "engine/ui/overlay_render_pass.h"

namespace qlight::ui {
namespace {

// Generous bounds so a wedged driver ends in an error rather than a hang; a
// software rasterizer can take seconds for one large frame.
constexpr uint64_t kFrameTimeoutNs = 60'000'000'000ull;
constexpr uint64_t kAcquireTimeoutNs = 10'000'000'000ull;

gpu::Unique<VkSemaphore> createSemaphore(VkDevice device) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore s = VK_NULL_HANDLE;
  QL_VK(vkCreateSemaphore(device, &info, nullptr, &s));
  return gpu::Unique<VkSemaphore>(
      s, [device](VkSemaphore x) { vkDestroySemaphore(device, x, nullptr); });
}

}  // namespace

Presenter::Presenter(const gpu::Context& ctx, const GlfwWindow& window, bool vsync,
                     uint32_t framesInFlight)
    : ctx_(ctx), window_(window), vsync_(vsync) {
  if (!ctx.surface()) throw std::runtime_error("presenter: the context has no window surface");
  VkDevice device = ctx.device();
  slots_.resize(std::max(1u, framesInFlight));
  for (FrameSlot& s : slots_) {
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily();
    VkCommandPool pool = VK_NULL_HANDLE;
    QL_VK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
    s.pool = gpu::Unique<VkCommandPool>(
        pool, [device](VkCommandPool p) { vkDestroyCommandPool(device, p, nullptr); });
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    QL_VK(vkAllocateCommandBuffers(device, &alloc, &s.cmd));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // the first wait passes
    VkFence fence = VK_NULL_HANDLE;
    QL_VK(vkCreateFence(device, &fenceInfo, nullptr, &fence));
    s.done =
        gpu::Unique<VkFence>(fence, [device](VkFence f) { vkDestroyFence(device, f, nullptr); });
    s.acquired = createSemaphore(device);
  }
  WindowExtent extent = window.framebufferExtent();
  if (extent.width == 0 || extent.height == 0) extent = {1, 1};
  if (!recreate(extent)) throw std::runtime_error("presenter: the window surface has no area");
}

Presenter::~Presenter() { vkDeviceWaitIdle(ctx_.device()); }

void Presenter::setVsync(bool vsync) {
  if (vsync != vsync_) recreatePending_ = true;
  vsync_ = vsync;
}

bool Presenter::recreate(WindowExtent extent) {
  // Nothing may still use the old images, views or semaphores. The wait can take a while
  // (a frame on a software rasterizer): the surface is asked for its size after it.
  QL_VK(vkDeviceWaitIdle(ctx_.device()));
  VkSurfaceCapabilitiesKHR caps;
  QL_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physicalDevice(), ctx_.surface(), &caps));
  const VkExtent2D wanted{extent.width, extent.height};
  const VkExtent2D size = Swapchain::extentFor(caps, wanted);
  if (size.width == 0 || size.height == 0) return false;  // minimized: keep the old one
  framebuffers_.clear();
  renderFinished_.clear();
  auto next = std::make_unique<Swapchain>(ctx_, caps, wanted, vsync_,
                                          swapchain_ ? swapchain_->handle() : VK_NULL_HANDLE);
  swapchain_ = std::move(next);
  if (!renderPass_) {
    renderPass_ = createOverlayRenderPass(ctx_, swapchain_->format());
    renderPassFormat_ = swapchain_->format();
  } else if (swapchain_->format() != renderPassFormat_) {
    // Overlay pipelines were built for the first render pass; keep them valid.
    throw std::runtime_error("presenter: the surface changed its pixel format");
  }
  for (uint32_t i = 0; i < swapchain_->imageCount(); ++i) {
    framebuffers_.push_back(
        createFramebuffer(ctx_, renderPass_, swapchain_->view(i), swapchain_->extent()));
    renderFinished_.push_back(createSemaphore(ctx_.device()));
  }
  builtFor_ = extent;
  recreatePending_ = false;
  ++recreations_;
  return true;
}

std::optional<PresentTarget> Presenter::beginFrame() {
  FrameSlot& s = slots_[slot_];
  VkFence done = s.done;
  VkResult waited = vkWaitForFences(ctx_.device(), 1, &done, VK_TRUE, kFrameTimeoutNs);
  if (waited == VK_TIMEOUT)
    throw std::runtime_error("presenter: the GPU did not finish a frame within 60 s");
  QL_VK(waited);

  for (int attempt = 0; attempt < 3; ++attempt) {
    WindowExtent extent = window_.framebufferExtent();
    if (extent.width == 0 || extent.height == 0) return std::nullopt;  // minimized
    if (extent.width != builtFor_.width || extent.height != builtFor_.height)
      recreatePending_ = true;
    if (recreatePending_ && !recreate(extent)) return std::nullopt;

    uint32_t index = 0;
    VkResult r = vkAcquireNextImageKHR(ctx_.device(), swapchain_->handle(), kAcquireTimeoutNs,
                                       s.acquired, VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {  // the semaphore stays unsignaled: try again
      recreatePending_ = true;
      continue;
    }
    if (r == VK_TIMEOUT || r == VK_NOT_READY)
      throw std::runtime_error("presenter: no swapchain image became available within 10 s");
    if (r == VK_SUBOPTIMAL_KHR)
      recreatePending_ = true;  // the image is usable: present it, rebuild next frame
    else
      QL_VK(r);

    QL_VK(vkResetCommandPool(ctx_.device(), s.pool, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    QL_VK(vkBeginCommandBuffer(s.cmd, &begin));
    return PresentTarget{s.cmd, index, swapchain_->image(index), swapchain_->extent(),
                         framebuffers_[index]};
  }
  return std::nullopt;  // the surface keeps changing under us: skip this frame
}

void Presenter::endFrame(const PresentTarget& target) {
  FrameSlot& s = slots_[slot_];
  QL_VK(vkEndCommandBuffer(target.cmd));
  VkFence done = s.done;
  QL_VK(vkResetFences(ctx_.device(), 1, &done));

  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = s.acquired;
  wait.stageMask = kAcquireWaitStage;
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.semaphore = renderFinished_[target.imageIndex];
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = target.cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = 1;
  submit.pWaitSemaphoreInfos = &wait;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  submit.signalSemaphoreInfoCount = 1;
  submit.pSignalSemaphoreInfos = &signal;
  QL_VK(vkQueueSubmit2(ctx_.queue(), 1, &submit, s.done));

  VkSemaphore finished = renderFinished_[target.imageIndex];
  VkSwapchainKHR swapchain = swapchain_->handle();
  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &finished;
  present.swapchainCount = 1;
  present.pSwapchains = &swapchain;
  present.pImageIndices = &target.imageIndex;
  VkResult r = vkQueuePresentKHR(ctx_.queue(), &present);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR)
    recreatePending_ = true;
  else
    QL_VK(r);
  slot_ = (slot_ + 1) % uint32_t(slots_.size());
}

}  // namespace qlight::ui
