// Where cache points come from (van Mastrigt 5.1): darts, light paths shot from
// the scene's lights and traced on the GPU, whose landings are accepted on the
// CPU by rejection distance (photon-map set, or Poisson disk with the distance
// from ambient occlusion); and spawns, first hits of camera paths that no point
// covers, reported by the shade pass in fixed slots.
#pragma once
#include <memory>

#include "engine/gpu/compute_pipeline.h"
#include "engine/guiding/cache_point_set.h"
#include "engine/guiding/guiding_settings.h"
#include "engine/guiding/point_acceptance.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/pipeline_variants.h"

namespace qlight::guiding {

struct PointRadii {
  float rejectionMin = 0, rejectionMax = 0;
  float searchRadius = 0;  // of the shaders' nearest-point search
};

// From the settings, or from the budget and the scene's surface area when they say 0.
PointRadii choosePointRadii(const GuidingSettings& settings, float surfaceArea);

class PointGenerator {
 public:
  static constexpr uint32_t kSpawnCapacity = 4096;  // spawn report slots per frame

  explicit PointGenerator(const gpu::Context& ctx);

  // Throws the darts and adds the accepted points to `set` (in slot order of the
  // candidates, so the set does not depend on the GPU's timing). Clears the spawn reports.
  void throwDarts(ecs::Registry& registry, const render::GpuScene& scene,
                  const GuidingSettings& settings, const PointRadii& radii, uint32_t seed,
                  CachePointSet& set);
  // After a frame: the spawn reports accepted at the minimum rejection distance join `set`.
  // Returns how many did.
  uint32_t acceptSpawns(ecs::Registry& registry, const PointRadii& radii, CachePointSet& set);

  // Spawns are accepted against the points thrown so far (after the first throwDarts).
  bool spawning() const { return bool(acceptor_); }
  const gpu::Buffer& spawnReports() const { return spawn_; }
  uint64_t memoryBytes() const;  // GPU buffers

 private:
  const gpu::Context& ctx_;
  render::PipelineVariants darts_;  // guiding_darts, specialized on the scene
  gpu::Buffer spawn_;
  std::unique_ptr<gpu::Buffer> candidates_;
  std::unique_ptr<PointAcceptor> acceptor_;
};

}  // namespace qlight::guiding
