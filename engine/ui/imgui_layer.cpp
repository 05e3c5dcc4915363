#include "engine/ui/imgui_layer.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <stdexcept>
#include <string>

#include "engine/gpu/vk_check.h"

namespace qlight::ui {
namespace {

void checkImGuiVk(VkResult result) {
  if (result < 0)
    throw std::runtime_error(std::string("imgui_layer: Vulkan backend call failed: ") +
                             gpu::vkResultName(result));
}

gpu::Unique<VkDescriptorPool> createPool(VkDevice device) {
  // The 1.86 backend allocates one combined image sampler set (the font).
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  info.maxSets = 8;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  QL_VK(vkCreateDescriptorPool(device, &info, nullptr, &pool));
  return gpu::Unique<VkDescriptorPool>(
      pool, [device](VkDescriptorPool p) { vkDestroyDescriptorPool(device, p, nullptr); });
}

}  // namespace

ImGuiLayer::ImGuiLayer(const gpu::Context& ctx, const GlfwWindow& window,
                       const Presenter& presenter)
    : ctx_(ctx), pool_(createPool(ctx.device())) {
  try {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    imguiContext_ = true;
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
    ImGui::StyleColorsDark();
    if (!ImGui_ImplGlfw_InitForVulkan(window.handle(), true))
      throw std::runtime_error("imgui_layer: ImGui_ImplGlfw_InitForVulkan failed");
    glfwBackend_ = true;

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx.instance();
    info.PhysicalDevice = ctx.physicalDevice();
    info.Device = ctx.device();
    info.QueueFamily = ctx.queueFamily();
    info.Queue = ctx.queue();
    info.DescriptorPool = pool_;
    info.Subpass = 0;
    info.MinImageCount = presenter.swapchain().minImageCount();
    info.ImageCount = std::max(info.MinImageCount, presenter.swapchain().imageCount());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = &checkImGuiVk;
    if (!ImGui_ImplVulkan_Init(&info, presenter.overlayRenderPass()))
      throw std::runtime_error("imgui_layer: ImGui_ImplVulkan_Init failed");
    vulkanBackend_ = true;

    ctx.submitAndWait([](VkCommandBuffer cmd) {
      if (!ImGui_ImplVulkan_CreateFontsTexture(cmd))
        throw std::runtime_error("imgui_layer: font texture upload failed");
    });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
  } catch (...) {
    shutdown();
    throw;
  }
}

ImGuiLayer::~ImGuiLayer() { shutdown(); }

void ImGuiLayer::shutdown() {
  vkDeviceWaitIdle(ctx_.device());  // the backend frees buffers a frame may still read
  if (vulkanBackend_) ImGui_ImplVulkan_Shutdown();
  if (glfwBackend_) ImGui_ImplGlfw_Shutdown();
  if (imguiContext_) ImGui::DestroyContext();
  vulkanBackend_ = glfwBackend_ = imguiContext_ = false;
}

void ImGuiLayer::newFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::render(const PresentTarget& target, VkRenderPass overlayPass) {
  ImGui::Render();
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = overlayPass;
  begin.framebuffer = target.framebuffer;
  begin.renderArea = {{0, 0}, target.extent};
  vkCmdBeginRenderPass(target.cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), target.cmd);
  vkCmdEndRenderPass(target.cmd);
}

bool ImGuiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace qlight::ui
