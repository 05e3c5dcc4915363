#include "bench/traversal_vs_embree/qlight_tracer.h"

#include <chrono>
#include <stdexcept>

#include "engine/gpu/pass_recorder.h"
#include "engine/render/scene_accel.h"
#include "shaders/shared/bvh_types.h"
#include "shaders/shared/scene_types.h"

namespace qlight::bench {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::unique_ptr<gpu::Buffer> upload(const gpu::Context& ctx, const std::vector<glm::vec4>& texels,
                                    const std::string& name) {
  auto b = std::make_unique<gpu::Buffer>(ctx, std::max<size_t>(texels.size(), 1) * 16, name,
                                         gpu::kTexelTableUsage);
  if (!texels.empty()) b->upload(ctx, texels.data(), texels.size() * 16);
  return b;
}

// Specialization constant 3 of trace_rays.comp (0..2 are the workgroup size).
std::vector<uint32_t> query(bool anyHit) { return {0, 0, 0, anyHit ? 1u : 0u}; }

}  // namespace

DeviceRays::DeviceRays(const gpu::Context& ctx, const RaySet& set)
    : count_(uint32_t(set.rays.size())), anyHit_(set.anyHit) {
  size_t bytes = std::max<size_t>(set.rays.size(), 1) * sizeof(TraceRay);
  rayBuffer_ =
      std::make_unique<gpu::Buffer>(ctx, bytes, "trace.rays." + set.kind, gpu::kTexelTableUsage);
  if (!set.rays.empty())
    rayBuffer_->upload(ctx, set.rays.data(), set.rays.size() * sizeof(TraceRay));
  hitBuffer_ = std::make_unique<gpu::Buffer>(ctx, std::max<size_t>(count_, 1) * sizeof(TraceHit),
                                             "trace.hits." + set.kind,
                                             VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT);
  raysView_ = std::make_unique<gpu::BufferView>(ctx, *rayBuffer_, VK_FORMAT_R32G32B32A32_SFLOAT);
  hitsView_ = std::make_unique<gpu::BufferView>(ctx, *hitBuffer_, VK_FORMAT_R32G32B32A32_UINT);
}

std::vector<TraceHit> DeviceRays::readHits(const gpu::Context& ctx) const {
  std::vector<TraceHit> hits(count_);
  hitBuffer_->download(ctx, hits.data(), hits.size() * sizeof(TraceHit));
  return hits;
}

QlightTracer::QlightTracer(const gpu::Context& ctx, const WorldScene& scene)
    : ctx_(ctx),
      closest_(ctx, "trace_rays", query(false)),
      any_(ctx, "trace_rays", query(true)),
      timer_(ctx) {
  if (!timer_.enabled()) throw std::runtime_error("the Vulkan queue has no timestamps");
  render::SceneAccel accel;
  Clock::time_point start = Clock::now();
  accel.buildMeshes(scene.asset.meshes);
  blasMs_ = msSince(start);
  start = Clock::now();
  accel.buildInstances(scene.draws);
  tlasMs_ = msSince(start);
  nodes_ = upload(ctx, accel.nodeTexels(), "bvh.nodes");
  triangles_ = upload(ctx, accel.triangleTexels(), "bvh.triangles");
  instances_ = upload(ctx, accel.instanceTexels(), "bvh.instances");
  nodesView_ = std::make_unique<gpu::BufferView>(ctx, *nodes_, VK_FORMAT_R32G32B32A32_SFLOAT);
  trianglesView_ =
      std::make_unique<gpu::BufferView>(ctx, *triangles_, VK_FORMAT_R32G32B32A32_SFLOAT);
  instancesView_ =
      std::make_unique<gpu::BufferView>(ctx, *instances_, VK_FORMAT_R32G32B32A32_SFLOAT);
  bvhBytes_ = 16 * (accel.nodeTexels().size() + accel.triangleTexels().size() +
                    accel.instanceTexels().size());
  nodeCount_ = accel.nodeTexels().size() / shared::kBvhNodeTexels;
}

double QlightTracer::trace(const DeviceRays& rays) {
  const gpu::ComputePipeline& pipeline = rays.anyHit() ? any_ : closest_;
  shared::TraceRaysPush push{rays.count(), 0, 0, 0};
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    timer_.reset(cmd);
    gpu::PassRecorder rec(ctx_, cmd, &timer_);
    rec.pass("trace_rays", pipeline)
        .read(QL_BIND_BVH_NODES, *nodesView_)
        .read(QL_BIND_BVH_TRIS, *trianglesView_)
        .read(QL_BIND_BVH_INSTANCES, *instancesView_)
        .read(QL_BIND_TRACE_RAYS, rays.rays())
        .write(QL_BIND_TRACE_HITS, rays.hits())
        .push(push)
        .dispatchThreads(rays.count());
    rec.finish();
  });
  return timer_.collect(ctx_).at("trace_rays");
}

}  // namespace qlight::bench
