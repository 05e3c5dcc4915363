// The Vulkan instance, the chosen physical device, the logical device with
// one compute(+graphics) queue, and the validation messenger.
#pragma once
#include <vulkan/vulkan.h>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "engine/gpu/unique_handle.h"

namespace qlight::gpu {

class PipelineLibrary;

struct ContextOptions {
  // Khronos validation (with synchronization validation). Defaults to the
  // QLIGHT_VALIDATION environment variable (tests set it to 1).
  bool validation = false;
  // Picks the physical device whose name contains this text (case-insensitive).
  // Empty: the QLIGHT_DEVICE environment variable, else a discrete GPU first.
  std::string deviceName;
  // Instance extensions a window system needs (from glfwGetRequiredInstanceExtensions).
  std::vector<std::string> instanceExtensions;
  // Creates the presentation surface once the instance exists (windowed mode).
  std::function<VkSurfaceKHR(VkInstance)> createSurface;
  bool quiet = false;  // do not print the chosen device
};

ContextOptions defaultContextOptions();

class Context {
 public:
  explicit Context(ContextOptions options);
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context();

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  VkSurfaceKHR surface() const { return surface_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  std::string deviceName() const { return properties_.deviceName; }
  bool validationEnabled() const { return validation_; }
  bool hasFloatAtomicAdd() const { return floatAtomicAdd_; }
  // Nanoseconds per timestamp tick; 0 when the queue has no timestamps.
  double timestampPeriodNs() const { return timestampPeriodNs_; }

  // Refuses, up front and in one line, memory the device cannot hold: `what` (its purpose,
  // and what the user can lower) of `bytes`, bound as a storage buffer of that range when
  // `storageBuffer`, read through a texel view of `texels` elements (0: none); checked
  // against maxStorageBufferRange, maxTexelBufferElements and the largest memory heap.
  void requireBufferFits(const std::string& what, uint64_t bytes, bool storageBuffer,
                         uint64_t texels) const;

  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                          VkMemoryPropertyFlags preferred = 0) const;
  // Allocates memory of the first type with `required` properties that fits.
  Unique<VkDeviceMemory> allocate(const VkMemoryRequirements& requirements,
                                  VkMemoryPropertyFlags required,
                                  uint32_t* typeIndex = nullptr) const;

  // Device memory allocations alive now, and their bytes (the soak run watches them).
  struct MemoryInUse {
    int64_t allocations = 0, bytes = 0;
  };
  MemoryInUse memoryInUse() const { return {memoryInUse_->allocations, memoryInUse_->bytes}; }

  // Records with `record`, submits and waits (uploads, readbacks, tests).
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

  // Every warning or error the validation layer reported so far.
  std::vector<std::string> validationMessages() const;
  size_t validationMessageCount() const;
  void clearValidationMessages();

  // Names an object for debuggers and validation messages.
  void setName(uint64_t handle, VkObjectType type, const std::string& name) const;

  // The compute pipelines built on this device so far, kept for every later user.
  PipelineLibrary& pipelines() const { return *pipelines_; }

  PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL
  onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                      const VkDebugUtilsMessengerCallbackDataEXT*, void*);
  void createInstance(const ContextOptions& options);
  void pickPhysicalDevice(const ContextOptions& options);
  void createDevice();

  bool validation_ = false;
  bool floatAtomicAdd_ = false;
  // Shared with each allocation's deleter, which may run after the Context is gone.
  struct LiveMemory {
    std::atomic<int64_t> allocations{0}, bytes{0};
  };
  std::shared_ptr<LiveMemory> memoryInUse_ = std::make_shared<LiveMemory>();
  double timestampPeriodNs_ = 0.0;
  Unique<VkInstance> instance_;
  Unique<VkDebugUtilsMessengerEXT> messenger_;
  Unique<VkSurfaceKHR> surface_;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  uint32_t queueFamily_ = 0;
  Unique<VkDevice> device_;
  VkQueue queue_ = VK_NULL_HANDLE;
  Unique<VkCommandPool> oneShotPool_;
  std::unique_ptr<PipelineLibrary> pipelines_;  // declared after device_: destroyed before it
  PFN_vkSetDebugUtilsObjectNameEXT setObjectName_ = nullptr;

  mutable std::mutex messagesMutex_;
  std::vector<std::string> messages_;
  // Tests of device loss: $QLIGHT_TEST_LOSE_DEVICE_AFTER=N makes the Nth submission report
  // VK_ERROR_DEVICE_LOST (no driver loses a device on request). Tests of the limits:
  // $QLIGHT_TEST_MAX_TEXEL_ELEMENTS lowers maxTexelBufferElements.
  uint64_t loseDeviceAfter_ = 0;
  mutable uint64_t submissions_ = 0;
};

}  // namespace qlight::gpu
