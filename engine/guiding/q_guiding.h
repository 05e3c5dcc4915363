// Q-learned importance sampling across frames (Dahm & Keller 2017, on the GPU
// as van Mastrigt 2018): cache points as ECS entities, their hashed grid, the
// Q tables (per point: strata values, visit counts, CDF) and the learned
// light-selection values V, with the passes that update them each frame.
#pragma once
#include <memory>
#include <string>

#include "engine/ecs/registry.h"
#include "engine/gpu/prefix_sum.h"
#include "engine/guiding/guiding_settings.h"
#include "engine/guiding/point_grid.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/null_guiding.h"

namespace qlight::guiding {

struct GuidingStats {
  uint32_t points = 0;
  uint32_t strata = 0;
  uint32_t lightsLearned = 0;  // 0 when light learning is off
  float rejectionMin = 0, rejectionMax = 0, searchRadius = 0;
  uint32_t spawnedPoints = 0;  // added from camera paths since generation
};

class QGuiding {
 public:
  QGuiding(const gpu::Context& ctx, const GuidingSettings& settings);
  ~QGuiding();

  // New settings. Strata or table settings reset the tables; point settings
  // regenerate the points at the next generatePoints.
  void setSettings(const GuidingSettings& settings);
  const GuidingSettings& settings() const { return settings_; }
  bool needsPoints() const { return needsPoints_; }

  // (Re)builds the cache points from darts shot from the scene's lights, as
  // CachePoint entities in `registry`, and resets the learned tables.
  void generatePoints(ecs::Registry& registry, const render::GpuScene& scene);

  void bind(gpu::PassBuilder& pass) const;
  render::GuidingBinder binder() const;
  // After the frame's path tracing: apply the Q (and V) updates, then the CDFs.
  void recordLearning(gpu::PassRecorder& recorder);
  // After the frame finished on the GPU: adds points where camera paths found none.
  void afterFrame(ecs::Registry& registry);

  GuidingStats stats() const;
  // Q table of one point (strata values), for tests and the UI.
  std::vector<float> readQ(uint32_t point) const;

 private:
  struct Tables;
  void allocate(uint32_t lightCount);  // everything (point buffers emptied)
  void allocateTables(uint32_t lightCount);
  void resetTables();
  void recordTables(gpu::PassRecorder& recorder, uint32_t rows);  // update + CDFs of the first rows
  void uploadPoints(ecs::Registry& registry);
  void writeUniforms();
  void chooseRadii(const render::GpuScene& scene);

  const gpu::Context& ctx_;
  GuidingSettings settings_;
  gpu::PrefixSum scan_;
  gpu::ComputePipeline update_, darts_;
  std::unique_ptr<Tables> t_;
  PointGrid grid_;
  uint32_t pointCount_ = 0;
  uint32_t lightCount_ = 0;     // lights with learned values
  uint32_t sceneLights_ = 0;
  float rejectionMin_ = 0, rejectionMax_ = 0, searchRadius_ = 0;
  uint32_t spawned_ = 0;
  bool needsPoints_ = true;
  uint32_t generation_ = 0;
  uint32_t lightFrame_ = 0;     // counts learning passes, for the light-value update interval
};

}  // namespace qlight::guiding
