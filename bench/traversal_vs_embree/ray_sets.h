// The three ray sets traced by both sides, made on the CPU from a fixed seed
// so every run and both tracers see the very same rays:
//   camera:     one ray per pixel, jittered as qlight's camera pass does
//               (pixel centres would put whole rows of hits exactly on the
//               box edges of a centred camera), scanline order (coherent);
//   incoherent: from the surface points the camera rays hit, uniform random
//               directions in the hemisphere on the side the camera saw;
//   shadow:     from those points towards random points on the emitters
//               (any-hit, tMax just short of the target).
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "bench/traversal_vs_embree/world_scene.h"
#include "shaders/shared/trace_rays.h"

namespace qlight::bench {

using shared::TraceHit;
using shared::TraceRay;

struct RaySet {
  std::string kind;  // "camera", "incoherent", "shadow"
  bool anyHit = false;
  std::vector<TraceRay> rays;
};

// Unbounded rays end here, on both sides (qlight's kInfinity).
inline constexpr float kRayInfinity = 1e30f;

RaySet cameraRays(const render::CameraView& camera, uint32_t width, uint32_t height, uint32_t seed);

// Secondary sets, one ray per camera ray: ray i starts where camera ray i hit
// (a random hit point where it missed), moved off the surface the way
// qlight's path tracer does (offsetRayOrigin). `cameraHits` are the closest
// hits of `camera` (either tracer's). Throws if no camera ray hit anything.
RaySet incoherentRays(const WorldScene& scene, const RaySet& camera,
                      std::span<const TraceHit> cameraHits, uint32_t seed);

// Targets: points on emissive triangles (by area), else point and spot light
// positions, else points in the scene bounds; only targets above the surface
// (as next event estimation keeps them), with a few retries per ray.
RaySet shadowRays(const WorldScene& scene, const RaySet& camera,
                  std::span<const TraceHit> cameraHits, uint32_t seed);

}  // namespace qlight::bench
