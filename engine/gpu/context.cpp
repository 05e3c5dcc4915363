#include "engine/gpu/context.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "engine/gpu/pipeline_library.h"
#include "engine/gpu/vk_check.h"

namespace qlight::gpu {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool envFlag(const char* name) {
  const char* v = std::getenv(name);
  return v && *v && std::strcmp(v, "0") != 0;
}

// Mesa and the loader warn when XDG_RUNTIME_DIR is unset; give them a private one.
void ensureRuntimeDir() {
  if (std::getenv("XDG_RUNTIME_DIR")) return;
  std::string dir = "/tmp/qlight-runtime-" + std::to_string(getuid());
  std::filesystem::create_directories(dir);
  std::filesystem::permissions(dir, std::filesystem::perms::owner_all,
                               std::filesystem::perm_options::replace);
  setenv("XDG_RUNTIME_DIR", dir.c_str(), 0);
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> exts(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data());
  for (auto& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

int deviceTypeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 1;
    default:
      return 0;
  }
}

}  // namespace

ContextOptions defaultContextOptions() {
  ContextOptions options;
  options.validation = envFlag("QLIGHT_VALIDATION");
  return options;
}

Context::Context(ContextOptions options) {
  ensureRuntimeDir();
  createInstance(options);
  if (options.createSurface) {
    VkInstance inst = instance_;
    surface_ = Unique<VkSurfaceKHR>(options.createSurface(inst), [inst](VkSurfaceKHR s) {
      vkDestroySurfaceKHR(inst, s, nullptr);
    });
  }
  pickPhysicalDevice(options);
  createDevice();
  pipelines_ = std::make_unique<PipelineLibrary>(*this);
  if (const char* n = std::getenv("QLIGHT_TEST_LOSE_DEVICE_AFTER"); n && *n)
    loseDeviceAfter_ = std::strtoull(n, nullptr, 10);
  // Tests of the limits on a device whose real ones no small scene reaches.
  if (const char* n = std::getenv("QLIGHT_TEST_MAX_TEXEL_ELEMENTS"); n && *n)
    properties_.limits.maxTexelBufferElements = std::min<uint32_t>(
        properties_.limits.maxTexelBufferElements, uint32_t(std::strtoul(n, nullptr, 10)));
  if (!options.quiet)
    std::fprintf(stderr, "qlight: Vulkan device \"%s\"%s\n", properties_.deviceName,
                 validation_ ? " (validation on)" : "");
}

Context::~Context() {
  if (device_) vkDeviceWaitIdle(device_);
}

void Context::createInstance(const ContextOptions& options) {
  validation_ = options.validation;
  const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
  if (validation_ && !hasLayer(kValidationLayer))
    throw std::runtime_error(
        "validation requested but VK_LAYER_KHRONOS_validation is not installed "
        "(apt-get install vulkan-validationlayers)");

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "qlight";
  app.pEngineName = "qlight";
  app.apiVersion = VK_API_VERSION_1_3;

  std::vector<const char*> extensions;
  for (auto& e : options.instanceExtensions) extensions.push_back(e.c_str());
  extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  std::vector<const char*> layers;
  if (validation_) layers.push_back(kValidationLayer);

  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                  VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &Context::onValidationMessage;
  messengerInfo.pUserData = this;

  // Synchronization validation catches a missing barrier as a hazard message.
  // QLIGHT_SYNC_VALIDATION=0 leaves it out: in Debian 12's layer (1.3.239) it keeps about
  // 150 KB per frame of history that it never frees, which long runs cannot afford
  // (tools/soak.sh).
  VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  const char* sync = std::getenv("QLIGHT_SYNC_VALIDATION");
  features.enabledValidationFeatureCount = sync && std::string(sync) == "0" ? 0 : 1;
  features.pEnabledValidationFeatures = enables;
  features.pNext = &messengerInfo;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  info.enabledLayerCount = uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  if (validation_) info.pNext = &features;

  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw std::runtime_error(
        "no Vulkan 1.3 driver found (on a machine without a GPU: apt-get install "
        "mesa-vulkan-drivers)");
  QL_VK(result);
  instance_ = Unique<VkInstance>(instance, [](VkInstance i) { vkDestroyInstance(i, nullptr); });

  auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
  auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
  if (validation_ && createMessenger) {
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    QL_VK(createMessenger(instance, &messengerInfo, nullptr, &messenger));
    messenger_ = Unique<VkDebugUtilsMessengerEXT>(
        messenger, [instance, destroyMessenger](VkDebugUtilsMessengerEXT m) {
          destroyMessenger(instance, m, nullptr);
        });
  }
}

void Context::pickPhysicalDevice(const ContextOptions& options) {
  uint32_t count = 0;
  QL_VK(vkEnumeratePhysicalDevices(instance_, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  QL_VK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));
  if (devices.empty())
    throw std::runtime_error("no Vulkan device found (apt-get install mesa-vulkan-drivers)");

  std::string wanted = options.deviceName;
  if (wanted.empty() && std::getenv("QLIGHT_DEVICE")) wanted = std::getenv("QLIGHT_DEVICE");
  wanted = lower(wanted);

  VkPhysicalDevice best = VK_NULL_HANDLE;
  int bestRank = -1;
  std::string names;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    names += std::string(names.empty() ? "" : ", ") + "\"" + p.deviceName + "\"";
    if (p.apiVersion < VK_API_VERSION_1_3) continue;
    if (!hasDeviceExtension(d, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME)) continue;
    if (surface_ && !hasDeviceExtension(d, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) continue;
    if (!wanted.empty() && lower(p.deviceName).find(wanted) == std::string::npos) continue;
    int rank = deviceTypeRank(p.deviceType);
    if (rank > bestRank) {
      best = d;
      bestRank = rank;
    }
  }
  if (!best) {
    if (!wanted.empty())
      throw std::runtime_error("no Vulkan 1.3 device matches \"" + wanted +
                               "\"; devices: " + names);
    throw std::runtime_error("no Vulkan 1.3 device with VK_KHR_push_descriptor; devices: " + names);
  }
  physical_ = best;
  vkGetPhysicalDeviceProperties(physical_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);

  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, families.data());
  bool found = false;
  for (uint32_t i = 0; i < familyCount && !found; ++i) {
    VkQueueFlags need = VK_QUEUE_COMPUTE_BIT | (surface_ ? VK_QUEUE_GRAPHICS_BIT : 0);
    if ((families[i].queueFlags & need) != need) continue;
    if (surface_) {
      VkBool32 present = VK_FALSE;
      vkGetPhysicalDeviceSurfaceSupportKHR(physical_, i, surface_, &present);
      if (!present) continue;
    }
    queueFamily_ = i;
    found = true;
    timestampPeriodNs_ = families[i].timestampValidBits ? properties_.limits.timestampPeriod : 0.0;
  }
  if (!found)
    throw std::runtime_error(std::string("device \"") + properties_.deviceName +
                             "\" has no compute queue" + (surface_ ? " that can present" : ""));
}

void Context::createDevice() {
  std::vector<const char*> extensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
  if (surface_) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

  VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFloat{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  v13.pNext = &v12;
  supported.pNext = &v13;
  bool atomicExt = hasDeviceExtension(physical_, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
  if (atomicExt) v12.pNext = &atomicFloat;
  vkGetPhysicalDeviceFeatures2(physical_, &supported);
  // 64-bit storage-buffer atomics: the learning targets' fixed-point sums take one atomic each
  // (every desktop GPU and lavapipe have them).
  if (!v12.scalarBlockLayout || !v13.synchronization2 || !v12.shaderBufferInt64Atomics ||
      !supported.features.shaderInt64)
    throw std::runtime_error(std::string("device \"") + properties_.deviceName +
                             "\" lacks scalarBlockLayout, synchronization2 or 64-bit atomics");

  floatAtomicAdd_ = atomicExt && atomicFloat.shaderBufferFloat32AtomicAdd;

  VkPhysicalDeviceShaderAtomicFloatFeaturesEXT enableAtomic{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
  enableAtomic.shaderBufferFloat32AtomicAdd = VK_TRUE;
  if (floatAtomicAdd_) extensions.push_back(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);

  VkPhysicalDeviceVulkan12Features enable12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  enable12.scalarBlockLayout = VK_TRUE;
  enable12.shaderBufferInt64Atomics = VK_TRUE;
  enable12.hostQueryReset = v12.hostQueryReset;
  enable12.pNext = floatAtomicAdd_ ? &enableAtomic : nullptr;
  VkPhysicalDeviceVulkan13Features enable13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  enable13.synchronization2 = VK_TRUE;
  enable13.maintenance4 = v13.maintenance4;
  enable13.pNext = &enable12;
  VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  enable.features.shaderInt64 = VK_TRUE;
  enable.features.shaderStorageImageWriteWithoutFormat =
      supported.features.shaderStorageImageWriteWithoutFormat;
  enable.pNext = &enable13;

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &enable;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  QL_VK(vkCreateDevice(physical_, &info, nullptr, &device));
  device_ = Unique<VkDevice>(device, [](VkDevice d) { vkDestroyDevice(d, nullptr); });
  vkGetDeviceQueue(device, queueFamily_, 0, &queue_);

  cmdPushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(device, "vkCmdPushDescriptorSetKHR"));
  setObjectName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
      vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  VkCommandPool pool = VK_NULL_HANDLE;
  QL_VK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
  oneShotPool_ = Unique<VkCommandPool>(
      pool, [device](VkCommandPool p) { vkDestroyCommandPool(device, p, nullptr); });
}

void Context::requireBufferFits(const std::string& what, uint64_t bytes, bool storageBuffer,
                                uint64_t texels) const {
  const VkPhysicalDeviceLimits& limits = properties_.limits;
  uint64_t heap = 0;
  for (uint32_t i = 0; i < memory_.memoryHeapCount; ++i)
    heap = std::max<uint64_t>(heap, memory_.memoryHeaps[i].size);
  auto mib = [](uint64_t b) { return std::to_string((b + (1u << 20) - 1) >> 20) + " MiB"; };
  std::string problem;
  if (storageBuffer && bytes > limits.maxStorageBufferRange)
    problem = "needs a buffer of " + mib(bytes) + "; the device allows " +
              mib(limits.maxStorageBufferRange) + " (maxStorageBufferRange)";
  else if (texels > limits.maxTexelBufferElements)
    problem = "needs " + std::to_string(texels) + " texels in one buffer; the device allows " +
              std::to_string(limits.maxTexelBufferElements) + " (maxTexelBufferElements)";
  else if (bytes > heap)
    problem = "needs " + mib(bytes) + "; the device's largest memory heap has " + mib(heap);
  if (!problem.empty())
    throw std::runtime_error(what + " is larger than " + deviceName() + " allows: it " + problem);
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                 VkMemoryPropertyFlags preferred) const {
  for (int pass = 0; pass < 2; ++pass) {
    VkMemoryPropertyFlags want = pass == 0 ? (required | preferred) : required;
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
      if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & want) == want) return i;
  }
  throw std::runtime_error("no Vulkan memory type with the required properties");
}

Unique<VkDeviceMemory> Context::allocate(const VkMemoryRequirements& req,
                                         VkMemoryPropertyFlags required,
                                         uint32_t* typeIndex) const {
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = findMemoryType(req.memoryTypeBits, required);
  if (typeIndex) *typeIndex = alloc.memoryTypeIndex;
  VkDevice device = device_;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  QL_VK(vkAllocateMemory(device, &alloc, nullptr, &memory));
  std::shared_ptr<LiveMemory> live = memoryInUse_;
  const int64_t bytes = int64_t(req.size);
  live->allocations++;
  live->bytes += bytes;
  return Unique<VkDeviceMemory>(memory, [device, live, bytes](VkDeviceMemory m) {
    vkFreeMemory(device, m, nullptr);
    live->allocations--;
    live->bytes -= bytes;
  });
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = oneShotPool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  QL_VK(vkAllocateCommandBuffers(device_, &alloc, &cmd));
  VkDevice device = device_;
  VkCommandPool pool = oneShotPool_;
  Unique<VkCommandBuffer> owner(
      cmd, [device, pool](VkCommandBuffer c) { vkFreeCommandBuffers(device, pool, 1, &c); });
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  QL_VK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  QL_VK(vkEndCommandBuffer(cmd));

  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  QL_VK(vkCreateFence(device, &fenceInfo, nullptr, &fence));
  Unique<VkFence> fenceOwner(fence, [device](VkFence f) { vkDestroyFence(device, f, nullptr); });
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  QL_VK(vkQueueSubmit(queue_, 1, &submit, fence));
  VkResult waited = vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX);
  if (loseDeviceAfter_ > 0 && ++submissions_ >= loseDeviceAfter_) waited = VK_ERROR_DEVICE_LOST;
  if (waited != VK_SUCCESS) throwVkError("vkWaitForFences", waited);
}

std::vector<std::string> Context::validationMessages() const {
  std::lock_guard lock(messagesMutex_);
  return messages_;
}

size_t Context::validationMessageCount() const {
  std::lock_guard lock(messagesMutex_);
  return messages_.size();
}

void Context::clearValidationMessages() {
  std::lock_guard lock(messagesMutex_);
  messages_.clear();
}

void Context::setName(uint64_t handle, VkObjectType type, const std::string& name) const {
  if (!setObjectName_ || !handle) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  setObjectName_(device_, &info);
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onValidationMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<Context*>(user);
  // Compute images stay in GENERAL by design (no per-pass layout changes); the
  // best-practice hint to copy from TRANSFER_SRC_OPTIMAL does not apply.
  constexpr int32_t kGeneralLayoutCopyHint = 0x4dae5635;
  if (data && data->messageIdNumber == kGeneralLayoutCopyHint) return VK_FALSE;
  std::string text = std::string(severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT
                                     ? "validation error: "
                                     : "validation warning: ") +
                     (data && data->pMessage ? data->pMessage : "");
  std::fprintf(stderr, "qlight: %s\n", text.c_str());
  std::lock_guard lock(self->messagesMutex_);
  self->messages_.push_back(std::move(text));
  return VK_FALSE;
}

}  // namespace qlight::gpu
