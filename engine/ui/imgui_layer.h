// Dear ImGui (1.86) over a GLFW window and the presenter's overlay render pass:
// context, GLFW and Vulkan backends, the descriptor pool they draw from, the
// font texture. One instance at a time (ImGui keeps a global context).
#pragma once
#include <vulkan/vulkan.h>

#include "engine/gpu/context.h"
#include "engine/ui/glfw_window.h"
#include "engine/ui/presenter.h"

namespace qlight::ui {

class ImGuiLayer {
 public:
  // Installs ImGui's GLFW callbacks (chaining any installed before).
  ImGuiLayer(const gpu::Context& ctx, const GlfwWindow& window, const Presenter& presenter);
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;
  ~ImGuiLayer();

  // Starts an ImGui frame: widgets may be declared until render().
  void newFrame();
  // Ends the ImGui frame and records the overlay render pass over `target`
  // (always, even with no widgets: it moves the image to PRESENT_SRC_KHR).
  void render(const PresentTarget& target, VkRenderPass overlayPass);

  // ImGui uses the mouse / keyboard this frame: camera controls keep off.
  bool wantsMouse() const;
  bool wantsKeyboard() const;

 private:
  void shutdown();

  const gpu::Context& ctx_;
  gpu::Unique<VkDescriptorPool> pool_;
  bool imguiContext_ = false, glfwBackend_ = false, vulkanBackend_ = false;
};

}  // namespace qlight::ui
