#include "engine/render/pipeline_variants.h"

namespace qlight::render {

const gpu::ComputePipeline& PipelineVariants::get(const char* shader,
                                                  const std::vector<uint32_t>& features) {
  auto& slot = variants_[{shader, features}];
  if (!slot) slot = std::make_unique<gpu::ComputePipeline>(ctx_, shader, features);
  return *slot;
}

}  // namespace qlight::render
