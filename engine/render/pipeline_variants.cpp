#include "engine/render/pipeline_variants.h"

#include "shaders/shared/specialization.h"

namespace qlight::render {

uint32_t featureKey(const std::vector<uint32_t>& features) {
  uint32_t key = 0;
  for (uint32_t id = shared::kSpecUseTextures; id < features.size(); ++id)
    key |= (features[id] != 0 ? 1u : 0u) << (id - shared::kSpecUseTextures);
  return key;
}

const gpu::ComputePipeline& PipelineVariants::get(const char* shader,
                                                  const std::vector<uint32_t>& features) {
  auto& slot = variants_[{shader, featureKey(features)}];
  if (!slot) slot = std::make_unique<gpu::ComputePipeline>(ctx_, shader, features);
  return *slot;
}

}  // namespace qlight::render
