// A compute pipeline built from one embedded shader (shaders/NAME.comp). Its
// descriptor set 0 is a push-descriptor set whose layout is reflected from the
// SPIR-V; push constants are up to kMaxPushConstantBytes. The Vulkan objects come from the
// Context's PipelineLibrary, so copies and later renderers share them.
#pragma once
#include <vulkan/vulkan.h>

#include <memory>
#include <string>

#include "engine/gpu/context.h"
#include "engine/gpu/pipeline_library.h"
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

  VkPipeline handle() const { return objects_ ? objects_->pipeline.get() : VK_NULL_HANDLE; }
  VkPipelineLayout layout() const { return objects_ ? objects_->layout.get() : VK_NULL_HANDLE; }
  const ReflectedShader& reflection() const { return objects().reflection; }
  const std::string& name() const { return objects().name; }
  // Workgroup size from the shader (after specialization when it uses local_size_x_id = 0..2).
  uint32_t localSize(int axis) const { return objects().localSize[axis]; }

 private:
  const PipelineObjects& objects() const;
  std::shared_ptr<const PipelineObjects> objects_;
};

// Builds the objects of one pipeline (PipelineLibrary calls it once per key).
std::shared_ptr<const PipelineObjects> buildComputePipeline(
    const Context& ctx, const std::string& shaderName, const std::vector<uint32_t>& specialization);

}  // namespace qlight::gpu
