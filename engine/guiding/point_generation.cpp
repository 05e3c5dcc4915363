#include "engine/guiding/point_generation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/gpu/pass_recorder.h"

namespace qlight::guiding {
namespace {

constexpr uint64_t kSpawnBytes = PointGenerator::kSpawnCapacity * 2ull * sizeof(glm::vec4);

void clearSpawnReports(const gpu::Context& ctx, gpu::Buffer& spawn) {
  std::vector<uint8_t> zeros(kSpawnBytes, 0);
  spawn.upload(ctx, zeros.data(), zeros.size());
}

}  // namespace

PointRadii choosePointRadii(const GuidingSettings& s, float surfaceArea) {
  // Random sequential adsorption saturates at about 0.7 A / r^2 points on area A: aim
  // the darts at half the budget, leaving room for camera spawns.
  float area = std::max(surfaceArea, 1e-6f);
  float autoMin = std::sqrt(0.7f * area / (0.5f * float(s.pointBudget)));
  PointRadii r;
  r.rejectionMin = s.rejectionMin > 0 ? s.rejectionMin : autoMin;
  r.rejectionMax = s.pointSet == PointSet::PhotonMap ? r.rejectionMin
                   : s.rejectionMax > 0              ? s.rejectionMax
                                                     : 3.0f * r.rejectionMin;
  // Saturated darts leave no surface point much farther than the rejection distance from
  // a point; gaps are filled by camera spawns. A larger radius covers the same but visits
  // more points per search (9% of the shade pass at 1.25x on lavapipe).
  r.searchRadius = r.rejectionMax;
  return r;
}

PointGenerator::PointGenerator(const gpu::Context& ctx)
    : ctx_(ctx), darts_(ctx), spawn_(ctx, kSpawnBytes, "guiding.spawn") {
  clearSpawnReports(ctx, spawn_);
}

void PointGenerator::throwDarts(ecs::Registry& registry, const render::GpuScene& scene,
                                const GuidingSettings& settings, const PointRadii& radii,
                                uint32_t seed, CachePointSet& set) {
  const uint32_t capacity = settings.dartPaths * settings.dartBounces;  // a slot per landing
  candidates_ = std::make_unique<gpu::Buffer>(ctx_, std::max<uint64_t>(capacity * 32ull, 16),
                                              "guiding.candidates");
  clearSpawnReports(ctx_, spawn_);
  std::vector<glm::vec4> raw;  // per candidate: position + occlusion, normal
  if (scene.lightCount() > 0) {
    shared::DartsPush push{};
    push.pathCount = settings.dartPaths;
    push.maxBounces = settings.dartBounces;
    push.lightCount = scene.lightCount();
    push.seed = seed;
    push.sceneCenter = scene.boundsCenter();
    push.sceneRadius = scene.boundsRadius();
    push.aoRadius = radii.rejectionMax * 2.0f;
    push.aoRays = settings.pointSet == PointSet::PoissonAo ? 8 : 0;
    push.capacity = capacity;
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
      gpu::PassRecorder rec(ctx_, cmd);
      rec.fill("guiding.darts.clear", *candidates_, 0xffffffffu);  // NaN: slot unused
      auto pass =
          rec.pass("guiding.darts", darts_.get("guiding_darts", scene.specializationFeatures()));
      scene.bind(pass);
      pass.write(QL_BIND_DART_CANDIDATES, *candidates_).push(push).dispatchThreads(push.pathCount);
      rec.finish();
    });
    raw.resize(size_t(capacity) * 2);
    candidates_->download(ctx_, raw.data(), raw.size() * sizeof(glm::vec4));
  }
  acceptor_ = std::make_unique<PointAcceptor>(radii.rejectionMax, settings.normalCosine);
  for (size_t i = 0; 2 * i < raw.size() && set.count() < set.budget(); ++i) {
    if (!std::isfinite(raw[2 * i].x)) continue;  // the dart's path ended before this bounce
    PointCandidate c{glm::vec3(raw[2 * i]), glm::vec3(raw[2 * i + 1]), raw[2 * i].w};
    float radius =
        settings.pointSet == PointSet::PhotonMap
            ? radii.rejectionMin
            : radii.rejectionMax + (radii.rejectionMin - radii.rejectionMax) * c.occlusion;
    CachePoint accepted;
    if (acceptor_->tryAccept(c, radius, accepted)) set.add(registry, accepted);
  }
}

uint64_t PointGenerator::memoryBytes() const {
  return spawn_.size() + (candidates_ ? candidates_->size() : 0);
}

uint32_t PointGenerator::acceptSpawns(ecs::Registry& registry, const PointRadii& radii,
                                      CachePointSet& set) {
  if (!acceptor_) return 0;
  // Fixed slots (w = 1 where written this frame), read in slot order: the points added do
  // not depend on the GPU's timing.
  std::vector<glm::vec4> raw(kSpawnCapacity * 2ull);
  spawn_.download(ctx_, raw.data(), raw.size() * sizeof(glm::vec4));
  bool any = false;
  for (uint32_t i = 0; i < kSpawnCapacity && !any; ++i) any = raw[2 * i].w != 0.0f;
  if (!any) return 0;
  clearSpawnReports(ctx_, spawn_);
  uint32_t added = 0;
  for (uint32_t i = 0; i < kSpawnCapacity && set.count() < set.budget(); ++i) {
    if (raw[2 * i].w == 0.0f) continue;
    PointCandidate c{glm::vec3(raw[2 * i]), glm::vec3(raw[2 * i + 1]), 0.0f};
    CachePoint accepted;
    if (acceptor_->tryAccept(c, radii.rejectionMin, accepted) && set.add(registry, accepted))
      ++added;
  }
  return added;
}

}  // namespace qlight::guiding
