// Reads the descriptor bindings a compute shader declares straight from its
// SPIR-V, so descriptor layouts are derived from the shader and cannot drift.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace qlight::gpu {

struct ReflectedBinding {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  uint32_t count = 1;
  bool readOnly = false;  // declared `readonly` (NonWritable) in the shader
  std::string name;
};

struct ReflectedShader {
  std::vector<ReflectedBinding> bindings;  // sorted by (set, binding)
  uint32_t localSize[3] = {1, 1, 1};
  bool hasPushConstants = false;
};

// Throws std::runtime_error on malformed SPIR-V.
ReflectedShader reflectSpirv(std::span<const uint32_t> words);

const char* descriptorTypeName(VkDescriptorType type);

}  // namespace qlight::gpu
