// Renders a scene to a converged image in frames of a few samples each,
// gathering the counters and GPU pass times the stats file reports.
#pragma once
#include <map>
#include <string>

#include "engine/gpu/context.h"
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
};

struct OfflineRender {
  LinearImage image;
  RenderStats stats;
};

// `samplesPerFrame` of settings is the batch size; spp the total.
OfflineRender renderScene(const gpu::Context& ctx, const scene::SceneAsset& asset,
                          const RenderSettings& settings, uint32_t spp, float timeSeconds);

}  // namespace qlight::render
