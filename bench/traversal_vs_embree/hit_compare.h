// Do both tracers find the same hits? Per ray: hit or miss, and for closest
// hits the distance, within a tolerance relative to the scene size. The
// triangle each names is counted apart and is no mismatch: at a shared edge
// or vertex, or where surfaces touch, either triangle is a right answer
// (qlight's test is watertight, Embree's default one is not).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "shaders/shared/trace_rays.h"

namespace qlight::bench {

struct Agreement {
  uint64_t rays = 0;
  uint64_t qlightHits = 0;
  uint64_t embreeHits = 0;
  uint64_t hitMissDiffer = 0;        // one hit, the other missed
  uint64_t distanceDiffer = 0;       // both hit, t apart by more than the tolerance
  uint64_t otherTriangle = 0;        // both hit within tolerance, different instance/primitive
  double maxDistanceDifference = 0;  // over the rays both hit, relative to the scene size
  std::vector<uint32_t> examples;    // the first few mismatching rays

  uint64_t mismatches() const { return hitMissDiffer + distanceDiffer; }
  double mismatchFraction() const { return rays ? double(mismatches()) / double(rays) : 0.0; }
};

// `sceneSize` is the bounds diagonal; t may differ by relativeTolerance * sceneSize.
Agreement compareHits(std::span<const shared::TraceHit> qlight,
                      std::span<const shared::TraceHit> embree, bool anyHit, float sceneSize,
                      float relativeTolerance);

}  // namespace qlight::bench
