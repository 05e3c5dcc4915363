// Turns a failed Vulkan call into an exception that names the call and the result.
#pragma once
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace qlight::gpu {

const char* vkResultName(VkResult result);

[[noreturn]] void throwVkError(const char* call, VkResult result);

}  // namespace qlight::gpu

#define QL_VK(call)                                                                     \
  do {                                                                                  \
    VkResult ql_vk_result_ = (call);                                                    \
    if (ql_vk_result_ != VK_SUCCESS) ::qlight::gpu::throwVkError(#call, ql_vk_result_); \
  } while (0)
