#include "engine/ui/glfw_window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <stdexcept>

namespace qlight::ui {

GlfwWindow::GlfwWindow(uint32_t width, uint32_t height, const std::string& title) {
  if (!glfwVulkanSupported())
    throw std::runtime_error("glfw_window: GLFW found no Vulkan loader for this display");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!window) throw std::runtime_error("glfw_window: glfwCreateWindow failed");
  window_ = gpu::Unique<GLFWwindow*>(window, [](GLFWwindow* w) { glfwDestroyWindow(w); });
}

WindowExtent GlfwWindow::framebufferExtent() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {uint32_t(w > 0 ? w : 0), uint32_t(h > 0 ? h : 0)};
}

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }

void GlfwWindow::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

std::vector<std::string> GlfwWindow::requiredInstanceExtensions() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw std::runtime_error("glfw_window: GLFW reports no Vulkan surface extensions");
  return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR GlfwWindow::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VkResult result = glfwCreateWindowSurface(instance, window_, nullptr, &surface);
  if (result != VK_SUCCESS)
    throw std::runtime_error("glfw_window: glfwCreateWindowSurface failed (VkResult " +
                             std::to_string(int(result)) + ")");
  return surface;
}

}  // namespace qlight::ui
