// Deep Q guiding (issue 14; Comi 2019, chapter 3, online and on the GPU): a small network
// maps a vertex's position and normal to Q per hemisphere stratum. The paths sample from a
// target copy of it and write their vertices' experience into a replay ring; every frame
// the learn phase trains the online copy on a batch drawn from the ring (relative L2 loss
// on the returns, backpropagation and Adam in compute shaders) and every targetInterval
// frames copies it to the target. Sampling and pdf are the tables' (shaders/shared/dqn.h).
// With a baked grid (settings.dqnGrid) each target copy is also evaluated once per grid
// row, and the paths read the rows instead of running the network.
#pragma once
#include <memory>
#include <vector>

#include "engine/guiding/guide_bindings.h"
#include "engine/guiding/guiding_settings.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/guide.h"
#include "shaders/shared/dqn.h"

namespace qlight::guiding {

struct DqnStats {
  uint32_t parameters = 0;
  uint32_t steps = 0;  // training steps so far
  uint32_t recordsPerFrame = 0;
  uint32_t capacity = 0;  // records in the replay ring
  float confidence = 0;   // guided share factor
};

class DqnGuide final : public render::Guide {
 public:
  // `pathsPerFrame` sizes the replay ring.
  DqnGuide(const gpu::Context& ctx, const GuidingSettings& settings, const render::GpuScene& scene,
           uint64_t pathsPerFrame);

  void bind(gpu::PassBuilder& pass) const override;
  render::GuideFeatures features() const override;

  // Upload phase: this frame's uniforms (where its records go, the guided share).
  void upload();
  // Learn phase: the training steps, the record count reset, the target copy when due.
  void recordLearning(gpu::PassRecorder& rec);
  // Settings that keep the network's shape apply at once; `sameShape` says if they do.
  bool sameShape(const GuidingSettings& s) const;
  void setSettings(const GuidingSettings& s) { settings_ = s; }

  const GuidingSettings& settings() const { return settings_; }
  shared::DqnShape shape() const { return shape_; }
  DqnStats stats() const;
  uint64_t memoryBytes() const;

  // The online network's parameters (tests, the window's inspection); a new set for both
  // copies (tests).
  std::vector<float> readWeights() const;
  std::vector<float> readTargetWeights() const;
  void uploadWeights(const std::vector<float>& weights);
  // The last step's gradient and per-record losses (tests, stats).
  std::vector<float> readGradient() const;
  std::vector<float> readLosses() const;
  // The replay ring's records; a new ring (tests: its size must be capacity()).
  std::vector<shared::DqnRecord> readRecords() const;
  void uploadRecords(const std::vector<shared::DqnRecord>& records);
  uint32_t capacity() const { return capacity_; }
  // One training step on the ring now (tests): with apply false only the gradient.
  void trainNow(bool apply);
  // The baked grid's rows (shared/dqn.h dqnGridRow order; each the inclusive CDF of its
  // sampling weights, strata consecutive); empty without a grid.
  std::vector<float> readGridRows() const;
  // The online network's Q per stratum at each state (position01, normal), strata
  // consecutive per state.
  std::vector<float> evaluate(const std::vector<shared::DqnRecord>& states) const;
  // The state of a world position, as the paths encode it.
  glm::vec3 position01(glm::vec3 world) const;

  // He-initialised hidden layers, small output weights: Q starts near-uniform.
  static std::vector<float> initialWeights(shared::DqnShape shape, uint32_t seed);

 private:
  void recordStep(gpu::PassRecorder& rec, bool apply = true);
  void recordBake(gpu::PassRecorder& rec);  // the grid's rows from the target copy

  const gpu::Context& ctx_;
  GuidingSettings settings_;
  shared::DqnShape shape_;
  glm::vec3 sceneMin_, sceneInvExtent_;
  uint32_t parameters_, capacity_, quota_;
  gpu::ComputePipeline backprop_, adam_, evaluate_, bake_;
  gpu::Buffer guidingUniforms_;  // shared::GuidingUniforms, its dqn block included
  gpu::Buffer online_, target_;  // parameters; the paths read the target
  std::unique_ptr<gpu::BufferView> targetView_;
  gpu::Buffer moments_, gradient_, scratch_, losses_, records_, counter_;
  std::unique_ptr<gpu::Buffer> gridRows_;  // with a grid: its rows' CDFs
  std::unique_ptr<gpu::BufferView> gridView_;
  GuidePlaceholders placeholders_;  // the tables' bindings
  uint32_t steps_ = 0, frames_ = 0, frameStart_ = 0;
};

}  // namespace qlight::guiding
