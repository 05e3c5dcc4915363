// Compute pipelines shared by everything that records on one Context. Building one from
// SPIR-V is CPU work in the driver and the validation layer (lavapipe: NIR passes and SPIR-V
// checks, most of a small render's time), and a renderer, a bench method or a test builds a
// dozen. So each (shader, specialization) is built once per device and kept until the Context
// goes: a second renderer on the same device starts without building any.
#pragma once
#include <vulkan/vulkan.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "engine/gpu/spirv_reflect.h"
#include "engine/gpu/unique_handle.h"

namespace qlight::gpu {

class Context;

// The Vulkan objects of one built pipeline; immutable once built.
struct PipelineObjects {
  std::string name;
  ReflectedShader reflection;
  uint32_t localSize[3] = {1, 1, 1};
  Unique<VkShaderModule> module;
  Unique<VkDescriptorSetLayout> setLayout;
  Unique<VkPipelineLayout> layout;
  Unique<VkPipeline> pipeline;
};

class PipelineLibrary {
 public:
  explicit PipelineLibrary(const Context& ctx) : ctx_(ctx) {}

  // The pipeline of shaders/`shaderName`.comp with `specialization`, built on first use.
  std::shared_ptr<const PipelineObjects> get(const std::string& shaderName,
                                             const std::vector<uint32_t>& specialization);
  size_t size() const;

 private:
  const Context& ctx_;
  mutable std::mutex mutex_;
  std::map<std::pair<std::string, std::vector<uint32_t>>, std::shared_ptr<const PipelineObjects>>
      built_;
};

}  // namespace qlight::gpu
