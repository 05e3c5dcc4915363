// qlight's side: the renderer's two-level BVH (render::SceneAccel, the same
// build and texel layout the path tracer uploads), traced on the Vulkan
// device by shaders/trace_rays.comp with the shared traversal
// (shaders/shared/bvh_traverse.h), timed with GPU timestamps.
#pragma once
#include <memory>
#include <vector>

#include "bench/traversal_vs_embree/ray_sets.h"
#include "bench/traversal_vs_embree/world_scene.h"
#include "engine/gpu/buffer.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_timer.h"

namespace qlight::bench {

// One ray set on the device with room for its hits; uploaded once, traced many times.
class DeviceRays {
 public:
  DeviceRays(const gpu::Context& ctx, const RaySet& set);
  uint32_t count() const { return count_; }
  bool anyHit() const { return anyHit_; }
  const gpu::BufferView& rays() const { return *raysView_; }
  const gpu::BufferView& hits() const { return *hitsView_; }
  std::vector<TraceHit> readHits(const gpu::Context& ctx) const;

 private:
  uint32_t count_;
  bool anyHit_;
  // Views point at their buffers, so both stay where they are.
  std::unique_ptr<gpu::Buffer> rayBuffer_, hitBuffer_;
  std::unique_ptr<gpu::BufferView> raysView_, hitsView_;
};

class QlightTracer {
 public:
  QlightTracer(const gpu::Context& ctx, const WorldScene& scene);

  double blasBuildMs() const { return blasMs_; }   // every mesh's BVH (SceneAccel::buildMeshes)
  double tlasBuildMs() const { return tlasMs_; }   // the instance level (buildInstances)
  uint64_t bvhBytes() const { return bvhBytes_; }  // the three texel arrays on the device
  uint64_t nodeCount() const { return nodeCount_; }

  // One dispatch over every ray (closest or any hit as the set says); the
  // GPU milliseconds of the pass alone, from its timestamps.
  double trace(const DeviceRays& rays);

 private:
  const gpu::Context& ctx_;
  double blasMs_ = 0, tlasMs_ = 0;
  uint64_t bvhBytes_ = 0, nodeCount_ = 0;
  std::unique_ptr<gpu::Buffer> nodes_, triangles_, instances_;
  std::unique_ptr<gpu::BufferView> nodesView_, trianglesView_, instancesView_;
  gpu::ComputePipeline closest_, any_;
  gpu::GpuTimer timer_;
};

}  // namespace qlight::bench
