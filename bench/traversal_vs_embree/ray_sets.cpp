#include "bench/traversal_vs_embree/ray_sets.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shaders/shared/random.h"
#include "shaders/shared/ray_offset.h"
#include "shaders/shared/sampling.h"

namespace qlight::bench {
namespace {

using glm::vec3;

// Where the secondary rays of one camera ray start.
struct SurfacePoint {
  vec3 origin;  // offset off the surface, on the camera's side
  vec3 normal;  // unit geometric normal, facing the camera ray
};

// The camera rays' hit points, and which camera ray each secondary ray uses.
class SurfacePoints {
 public:
  SurfacePoints(const WorldScene& scene, const RaySet& camera, std::span<const TraceHit> hits) {
    if (hits.size() != camera.rays.size())
      throw std::logic_error("one hit per camera ray expected");
    points_.resize(hits.size());
    for (size_t i = 0; i < hits.size(); ++i) {
      if (!hits[i].hit) continue;
      const TraceRay& r = camera.rays[i];
      WorldTriangle tri = scene.triangle(hits[i].instance, hits[i].primitive);
      vec3 n = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
      float len = glm::length(n);
      if (!(len > 0.0f) || !std::isfinite(len)) continue;
      n /= len;
      if (glm::dot(n, r.dir) > 0.0f) n = -n;
      // As qlight resolves a hit: origin + t * dir, then the robust offset.
      points_[i] = {shared::offsetRayOrigin(r.origin + hits[i].t * r.dir, n), n};
      hitIndices_.push_back(uint32_t(i));
    }
    if (hitIndices_.empty())
      throw std::runtime_error(scene.name + ": no camera ray hits the scene");
  }
  // Camera ray i's point where it hit, else a random one of those that hit.
  const SurfacePoint& forRay(size_t i, shared::Rng& rng) const {
    bool hit = i < points_.size() && points_[i].normal != vec3(0.0f);
    return hit ? points_[i] : random(rng);
  }
  const SurfacePoint& random(shared::Rng& rng) const {
    return points_[hitIndices_[shared::rngNextUint(rng) % hitIndices_.size()]];
  }

 private:
  std::vector<SurfacePoint> points_;  // normal 0: the camera ray missed
  std::vector<uint32_t> hitIndices_;
};

// Per-set, per-ray streams: ray i's numbers do not depend on the others.
shared::Rng rayRng(size_t ray, uint32_t set, uint32_t seed) {
  return shared::rngSeed(uint32_t(ray), set, seed);
}

// Picks shadow-ray targets: emitters by area, else lights, else the bounds.
class TargetSampler {
 public:
  explicit TargetSampler(const WorldScene& scene) : scene_(scene) {
    float total = 0.0f;
    for (const WorldTriangle& t : scene.emitters) {
      total += shared::triangleArea(t.p0, t.p1, t.p2);
      areaCdf_.push_back(total);
    }
  }
  vec3 sample(shared::Rng& rng) const {
    if (!areaCdf_.empty()) {
      float u = shared::rngNextFloat(rng) * areaCdf_.back();
      size_t k = std::upper_bound(areaCdf_.begin(), areaCdf_.end(), u) - areaCdf_.begin();
      const WorldTriangle& t = scene_.emitters[std::min(k, areaCdf_.size() - 1)];
      return shared::sampleTrianglePoint(t.p0, t.p1, t.p2, shared::rngNext2(rng));
    }
    if (!scene_.punctualPositions.empty())
      return scene_.punctualPositions[shared::rngNextUint(rng) % scene_.punctualPositions.size()];
    return scene_.boundsMin + shared::rngNext3(rng) * (scene_.boundsMax - scene_.boundsMin);
  }

 private:
  const WorldScene& scene_;
  std::vector<float> areaCdf_;
};

constexpr uint32_t kCameraSet = 0;
constexpr uint32_t kIncoherentSet = 1;
constexpr uint32_t kShadowSet = 2;

}  // namespace

RaySet cameraRays(const render::CameraView& cam, uint32_t width, uint32_t height, uint32_t seed) {
  // The basis, pixel mapping and jitter of qlight's camera pass (pt_begin.comp).
  vec3 forward = glm::normalize(cam.forward);
  vec3 right = glm::normalize(glm::cross(forward, cam.up));
  vec3 up = glm::cross(right, forward);
  float tanHalf = std::tan(0.5f * cam.yfov);
  float aspect = float(width) / float(height);
  RaySet set{"camera", false, {}};
  set.rays.reserve(size_t(width) * height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      shared::Rng rng = rayRng(size_t(y) * width + x, kCameraSet, seed);
      glm::vec2 ndc =
          (glm::vec2(x, y) + shared::rngNext2(rng)) / glm::vec2(width, height) * 2.0f - 1.0f;
      vec3 dir = glm::normalize(forward + ndc.x * tanHalf * aspect * right - ndc.y * tanHalf * up);
      set.rays.push_back({cam.position, kRayInfinity, dir, 0.0f});
    }
  return set;
}

RaySet incoherentRays(const WorldScene& scene, const RaySet& camera,
                      std::span<const TraceHit> cameraHits, uint32_t seed) {
  SurfacePoints points(scene, camera, cameraHits);
  RaySet set{"incoherent", false, {}};
  set.rays.reserve(camera.rays.size());
  for (size_t i = 0; i < camera.rays.size(); ++i) {
    shared::Rng rng = rayRng(i, kIncoherentSet, seed);
    const SurfacePoint& p = points.forRay(i, rng);
    vec3 local = shared::sampleUniformHemisphere(shared::rngNext2(rng));
    vec3 dir = shared::worldFromLocal(shared::frameFromNormal(p.normal), local);
    set.rays.push_back({p.origin, kRayInfinity, glm::normalize(dir), 0.0f});
  }
  return set;
}

RaySet shadowRays(const WorldScene& scene, const RaySet& camera,
                  std::span<const TraceHit> cameraHits, uint32_t seed) {
  SurfacePoints points(scene, camera, cameraHits);
  TargetSampler targets(scene);
  RaySet set{"shadow", true, {}};
  set.rays.reserve(camera.rays.size());
  constexpr int kTries = 32;  // then the last pair is kept even if below the surface
  for (size_t i = 0; i < camera.rays.size(); ++i) {
    shared::Rng rng = rayRng(i, kShadowSet, seed);
    const SurfacePoint* p = &points.forRay(i, rng);
    vec3 target = targets.sample(rng);
    for (int k = 1; k < kTries && !(glm::dot(target - p->origin, p->normal) > 0.0f); ++k) {
      if (k % 4 == 0) p = &points.random(rng);  // this point may see no emitter at all
      target = targets.sample(rng);
    }
    vec3 d = target - p->origin;
    float dist = glm::length(d);
    if (!(dist > 0.0f)) {  // a target on the point itself: any unit ray will do
      d = p->normal;
      dist = 1.0f;
    }
    // As qlight's next event estimation: unit direction, tMax 1e-4 short of the target.
    set.rays.push_back({p->origin, dist * (1.0f - 1e-4f), d / dist, 0.0f});
  }
  return set;
}

}  // namespace qlight::bench
