#include "engine/gpu/vk_check.h"

namespace qlight::gpu {

const char* vkResultName(VkResult result) {
  switch (result) {
#define QL_CASE(x) \
  case x:          \
    return #x;
    QL_CASE(VK_SUCCESS)
    QL_CASE(VK_NOT_READY)
    QL_CASE(VK_TIMEOUT)
    QL_CASE(VK_INCOMPLETE)
    QL_CASE(VK_SUBOPTIMAL_KHR)
    QL_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    QL_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    QL_CASE(VK_ERROR_INITIALIZATION_FAILED)
    QL_CASE(VK_ERROR_DEVICE_LOST)
    QL_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    QL_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    QL_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    QL_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    QL_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    QL_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    QL_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    QL_CASE(VK_ERROR_SURFACE_LOST_KHR)
    QL_CASE(VK_ERROR_OUT_OF_DATE_KHR)
    QL_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
#undef QL_CASE
    default:
      return "VkResult(unknown)";
  }
}

void throwVkError(const char* call, VkResult result) {
  // The results a user can act on get words of their own; the call stays for a bug report.
  const std::string where = std::string(" (") + call + " -> " + vkResultName(result) + ")";
  if (result == VK_ERROR_DEVICE_LOST)
    throw std::runtime_error(
        "the Vulkan device was lost (a driver crash or a GPU reset); "
        "restart qlight" +
        where);
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw std::runtime_error(
        "out of " + std::string(result == VK_ERROR_OUT_OF_DEVICE_MEMORY ? "device" : "host") +
        " memory: lower the render size, --points or --strata" + where);
  throw std::runtime_error(std::string("Vulkan call failed: ") + call + " -> " +
                           vkResultName(result));
}

}  // namespace qlight::gpu
