// What a run of frames measured: the counters, GPU time per pass and the
// papers' measures (emitter hit share and mean path length per frame), summed
// by the offline render and the headless demo alike.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "engine/guiding/q_guide.h"
#include "engine/render/path_tracer.h"

namespace qlight::session {

// One frame, read back after its fence.
struct FrameResult {
  render::FrameCounters counters;
  std::map<std::string, double> gpuMs;  // per pass name
  uint32_t samples = 0;
  double emitterHitShare() const;
  double meanPathLength() const;
};

struct RenderStats {
  uint32_t width = 0, height = 0, spp = 0, frames = 0;
  double seconds = 0;  // wall time of the frames (not loading)
  render::FrameCounters counters;
  std::map<std::string, double> gpuMs;  // summed over frames, per pass name
  std::string device;
  bool traceInShade = false;  // the extension rays' trace fused into the shade pass
  uint32_t lights = 0;
  bool fallbackSky = false;
  bool glowMapsOnly = false;      // every emitter an emissive texture (GpuScene::glowMapsOnly)
  bool environmentLight = false;  // the user's environment lights the scene (not black)
  bool guided = false;
  bool deepQ = false;  // guided by the network (--guiding dqn), not the tables
  guiding::GuidingStats guidingStats;
  double pointGenerationSeconds = 0;
  // The scene on the GPU: triangles, device memory, and the time to build its BLASes and
  // the whole GPU scene (BVH and uploads).
  uint64_t triangles = 0, sceneGpuBytes = 0;
  double blasBuildSeconds = 0, sceneBuildSeconds = 0;
  // Per frame: share of paths that reached an emitter by a scattered ray, and
  // mean path length (how learning progresses).
  std::vector<double> emitterHitShareByFrame, pathLengthByFrame;

  void add(const FrameResult& frame);
};

}  // namespace qlight::session
