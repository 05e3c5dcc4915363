// Compute pipelines specialized on the scene's (and frame's) features, built once per
// feature set: every pass that reads the scene through include/scene_access.glsl should
// get its pipeline here, so that code for features the scene lacks (alpha tests, vertex
// extras, textures, ...) is not in it (lavapipe executes both sides of every branch).
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/gpu/compute_pipeline.h"

namespace qlight::render {

class PipelineVariants {
 public:
  explicit PipelineVariants(const gpu::Context& ctx) : ctx_(ctx) {}

  // `features`: specialization constant values by constant id (GpuScene::
  // specializationFeatures, plus any the caller sets).
  const gpu::ComputePipeline& get(const char* shader, const std::vector<uint32_t>& features);

 private:
  const gpu::Context& ctx_;
  // Keyed by the whole vector: some constants are counts (the deep Q network's shape, the
  // bounce phase), not switches.
  std::map<std::pair<std::string, std::vector<uint32_t>>, std::unique_ptr<gpu::ComputePipeline>>
      variants_;
};

}  // namespace qlight::render
