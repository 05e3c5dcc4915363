// Q-learned importance sampling across frames (Dahm & Keller 2017, on the GPU
// as van Mastrigt 2018), as the path tracer's guide. It composes the parts,
// each with one job: where points come from (PointGenerator), the points with
// their stable slots and grid (CachePointSet), what was learned (LearnedTables)
// and the bindings the path passes read (GuideBuffers).
#pragma once
#include <memory>
#include <vector>

#include "engine/ecs/registry.h"
#include "engine/guiding/cache_point_set.h"
#include "engine/guiding/guiding_settings.h"
#include "engine/guiding/learned_tables.h"
#include "engine/guiding/point_generation.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/guide.h"

namespace qlight::guiding {

struct GuidingStats {
  uint32_t points = 0;
  uint32_t strata = 0;
  uint32_t lightsLearned = 0;  // 0 when light learning is off
  float rejectionMin = 0, rejectionMax = 0, searchRadius = 0;
  uint32_t spawnedPoints = 0;  // added from camera paths since generation
};

class QGuide final : public render::Guide {
 public:
  QGuide(const gpu::Context& ctx, const GuidingSettings& settings);

  // New settings. Strata or table settings reset the tables (the points and their grid
  // stay); point settings regenerate the points at the next generatePoints.
  void setSettings(const GuidingSettings& settings);
  const GuidingSettings& settings() const { return settings_; }
  bool needsPoints() const { return needsPoints_; }

  // (Re)builds the cache points from darts shot from the scene's lights, as CachePoint
  // entities in `registry`, and resets the learned tables.
  void generatePoints(ecs::Registry& registry, const render::GpuScene& scene);
  // After a frame's fence: points where its camera paths found none join the set.
  void acceptSpawns(ecs::Registry& registry);
  // Upload phase: changed points and their grid to the GPU (fresh rows for reused slots);
  // nothing when no point changed.
  void uploadPoints(ecs::Registry& registry);
  // Learn phase, after the frame's path tracing: the Q (and V) updates, then the CDFs.
  void recordLearning(gpu::PassRecorder& recorder);
  // Upload phase: the lights moved this share of the scene's radius since the last frame
  // (tracking forgets settings().forgetOnLightMove halvings per radius at the next learning).
  // A jump (a halving or more) ages every row at once, before this frame's paths read the
  // points' confidence: they sample by the BSDF until the points have learned again.
  void noteLightMotion(float share);

  GuidingStats stats() const;
  // GPU memory of the guide's buffers: points, grid, tables, spawn reports, dart candidates.
  uint64_t memoryBytes() const;
  // Q of the point in `slot` (its strata values), for tests and the UI.
  std::vector<float> readQ(uint32_t slot) const { return tables_.readQ(slot); }
  // What was learned, for the window's views (engine/guiding/guide_inspection.h).
  const LearnedTables& tables() const { return tables_; }
  // The nearest-point search radius (0 before points exist).
  float searchRadius() const { return points_ ? points_->searchRadius() : 0.0f; }
  LearnedTables::ValueRange qRange() const { return tables_.qRange(); }

  void bind(gpu::PassBuilder& pass) const override;
  render::GuideFeatures features() const override;

 private:
  void writeUniforms();

  const gpu::Context& ctx_;
  GuidingSettings settings_;
  PointGenerator generator_;
  std::unique_ptr<CachePointSet> points_;
  LearnedTables tables_;
  gpu::Buffer uniforms_;  // shared::GuidingUniforms
  PointRadii radii_;
  uint32_t spawned_ = 0;
  bool needsPoints_ = true;
  uint32_t generation_ = 0;
};

}  // namespace qlight::guiding
