// A compute pipeline built from one embedded shader (shaders/NAME.comp). Its
// descriptor set 0 is a push-descriptor set whose layout is reflected from the
// SPIR-V; push constants are up to kMaxPushConstantBytes.
#pragma once
#include <vulkan/vulkan.h>

#include <string>

#include "engine/gpu/context.h"
#include "engine/gpu/spirv_reflect.h"

namespace qlight::gpu {

constexpr uint32_t kMaxPushConstantBytes = 128;

class ComputePipeline {
 public:
  ComputePipeline() = default;
  // `shaderName` is the file name without extension: "prefix_sum" for shaders/prefix_sum.comp.
  // Specialization constants (constant_id = i) take the values in `specialization`.
  ComputePipeline(const Context& ctx, const std::string& shaderName,
                  std::vector<uint32_t> specialization = {});

  VkPipeline handle() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_; }
  const ReflectedShader& reflection() const { return reflection_; }
  const std::string& name() const { return name_; }
  // Workgroup size from the shader (after specialization when it uses local_size_x_id = 0..2).
  uint32_t localSize(int axis) const { return localSize_[axis]; }

 private:
  std::string name_;
  ReflectedShader reflection_;
  uint32_t localSize_[3] = {1, 1, 1};
  Unique<VkShaderModule> module_;
  Unique<VkDescriptorSetLayout> setLayout_;
  Unique<VkPipelineLayout> layout_;
  Unique<VkPipeline> pipeline_;
};

}  // namespace qlight::gpu
