// Embree's side: the scene's world-space triangles in one rtcScene (one
// triangle geometry per qlight instance, geometry id = instance index, so
// hits name the same instance and primitive), built at high quality, traced
// with single-ray queries from plain std::threads on the same cores lavapipe
// uses. Embree is the reference for what single-ray CPU traversal can reach.
#pragma once
#include <embree3/rtcore.h>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "bench/traversal_vs_embree/ray_sets.h"
#include "bench/traversal_vs_embree/world_scene.h"

namespace qlight::bench {

class EmbreeTracer {
 public:
  // `threads` drives both the build (Embree's TBB pool) and the tracing.
  EmbreeTracer(const WorldScene& scene, unsigned threads);
  EmbreeTracer(const EmbreeTracer&) = delete;
  EmbreeTracer& operator=(const EmbreeTracer&) = delete;

  double geometryMs() const { return geometryMs_; }  // buffers filled and committed
  double buildMs() const { return buildMs_; }        // rtcCommitScene: the BVH build
  // Bytes Embree holds after the build (its memory monitor): BVH plus vertex and index copies.
  int64_t memoryBytes() const { return memory_->current.load(); }
  int64_t peakMemoryBytes() const { return memory_->peak.load(); }
  // The committed scene (geometry id = instance index), for other single-ray users.
  RTCScene scene() const { return scene_.get(); }

  // Every ray through rtcIntersect1 (closest hit) or rtcOccluded1 (any hit),
  // spread over the threads in small chunks; fills `hits` (one per ray) and
  // returns the wall-clock milliseconds.
  double trace(const RaySet& set, std::vector<TraceHit>& hits) const;
  // The same with 8-ray packets (rtcIntersect8 / rtcOccluded8), for reference only.
  double tracePackets8(const RaySet& set, std::vector<TraceHit>& hits) const;

 private:
  struct Memory {
    std::atomic<int64_t> current{0};
    std::atomic<int64_t> peak{0};
  };
  struct DeviceDeleter {
    void operator()(RTCDevice d) const { rtcReleaseDevice(d); }
  };
  struct SceneDeleter {
    void operator()(RTCScene s) const { rtcReleaseScene(s); }
  };
  static bool onMemory(void* user, ssize_t bytes, bool post);
  void check(const char* what) const;

  unsigned threads_;
  std::unique_ptr<Memory> memory_;  // the monitor callback holds its address
  std::unique_ptr<RTCDeviceTy, DeviceDeleter> device_;
  std::unique_ptr<RTCSceneTy, SceneDeleter> scene_;
  double geometryMs_ = 0;
  double buildMs_ = 0;
};

// "3.13.5", from the library's own headers.
std::string embreeVersion();

}  // namespace qlight::bench
