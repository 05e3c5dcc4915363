// Renders a scene to a converged image in frames of a few samples each, with
// Q-learned guiding across the frames, gathering the counters and GPU pass
// times the stats file reports.
#pragma once
#include <functional>

#include "engine/gpu/context.h"
#include "engine/guiding/guiding_settings.h"
#include "engine/image/image_io.h"
#include "engine/render/render_settings.h"
#include "engine/scene/scene_asset.h"
#include "engine/session/render_stats.h"

namespace qlight::session {

struct OfflineRender {
  image::LinearImage image;
  RenderStats stats;
};

guiding::GuidingSettings disabledGuiding();

// `samplesPerFrame` of settings is the batch size; spp the total. Guiding
// learns across the batches (disabled when guiding.enabled is false). `progress`, when
// given, hears the samples per pixel done after each batch.
OfflineRender renderScene(const gpu::Context& ctx, const scene::SceneAsset& asset,
                          const render::RenderSettings& settings, uint32_t spp, float timeSeconds,
                          const guiding::GuidingSettings& guiding = disabledGuiding(),
                          const std::function<void(uint32_t sppDone)>& progress = {});

}  // namespace qlight::session
