// Renders a scene to a converged image in frames of a few samples each, with
// Q-learned guiding across the frames, gathering the counters and GPU pass
// times the stats file reports.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "engine/gpu/context.h"
#include "engine/guiding/guiding_settings.h"
#include "engine/guiding/q_guiding.h"
#include "engine/render/path_tracer.h"
#include "engine/scene/scene_asset.h"

namespace qlight::render {

struct RenderStats {
  uint32_t width = 0, height = 0, spp = 0, frames = 0;
  double seconds = 0;  // wall time of the frames (not loading)
  FrameCounters counters;
  std::map<std::string, double> gpuMs;  // summed over frames, per pass name
  std::string device;
  uint32_t lights = 0;
  bool fallbackSky = false;
  bool guided = false;
  guiding::GuidingStats guidingStats;
  double pointGenerationSeconds = 0;
  // Per frame: share of paths that reached an emitter by a scattered ray, and
  // mean path length (how learning progresses).
  std::vector<double> emitterHitShareByFrame, pathLengthByFrame;
};

struct OfflineRender {
  LinearImage image;
  RenderStats stats;
};

guiding::GuidingSettings disabledGuiding();

// `samplesPerFrame` of settings is the batch size; spp the total. Guiding
// learns across the batches (disabled when guiding.enabled is false).
OfflineRender renderScene(const gpu::Context& ctx, const scene::SceneAsset& asset,
                          const RenderSettings& settings, uint32_t spp, float timeSeconds,
                          const guiding::GuidingSettings& guiding = disabledGuiding());

}  // namespace qlight::render
