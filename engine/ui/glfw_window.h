// An OS window for Vulkan presentation (GLFW, no client API), and the pieces a
// gpu::Context needs to present into it: instance extensions and a surface.
#pragma once
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "engine/gpu/unique_handle.h"

struct GLFWwindow;

namespace qlight::ui {

struct WindowExtent {
  uint32_t width = 0, height = 0;  // pixels of the framebuffer; 0 while minimized
};

class GlfwWindow {
 public:
  // glfwInit() must have succeeded. Throws std::runtime_error when GLFW has no
  // Vulkan support or the window cannot be created.
  GlfwWindow(uint32_t width, uint32_t height, const std::string& title);

  GLFWwindow* handle() const { return window_; }
  WindowExtent framebufferExtent() const;
  bool shouldClose() const;
  void requestClose();

  // What the Vulkan instance must enable to present into a GLFW window.
  static std::vector<std::string> requiredInstanceExtensions();
  // Creates the window's surface on `instance` (the Context owns and destroys it).
  VkSurfaceKHR createSurface(VkInstance instance) const;

 private:
  gpu::Unique<GLFWwindow*> window_;
};

}  // namespace qlight::ui
