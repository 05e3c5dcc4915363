#include "engine/gpu/pipeline_library.h"

#include "engine/gpu/compute_pipeline.h"

namespace qlight::gpu {

std::shared_ptr<const PipelineObjects> PipelineLibrary::get(
    const std::string& shaderName, const std::vector<uint32_t>& specialization) {
  std::lock_guard lock(mutex_);
  auto key = std::make_pair(shaderName, specialization);
  if (auto it = built_.find(key); it != built_.end()) return it->second;
  // Built before it is stored: a shader that fails to build leaves no entry behind.
  auto built = buildComputePipeline(ctx_, shaderName, specialization);
  built_.emplace(std::move(key), built);
  return built;
}

size_t PipelineLibrary::size() const {
  std::lock_guard lock(mutex_);
  return built_.size();
}

}  // namespace qlight::gpu
