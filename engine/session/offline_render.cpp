#include "engine/session/offline_render.h"

#include <algorithm>
#include <chrono>

#include "engine/session/renderer.h"

namespace qlight::session {

guiding::GuidingSettings disabledGuiding() {
  guiding::GuidingSettings g;
  g.enabled = false;
  return g;
}

OfflineRender renderScene(const gpu::Context& ctx, const scene::SceneAsset& asset,
                          const render::RenderSettings& settings, uint32_t spp, float timeSeconds,
                          const guiding::GuidingSettings& guidingSettings,
                          const std::function<void(uint32_t sppDone)>& progress) {
  using Clock = std::chrono::steady_clock;
  Renderer renderer(ctx, asset, settings, guidingSettings);
  OfflineRender out;
  out.stats = renderer.newStats();
  auto start = Clock::now();
  while (out.stats.spp < spp) {
    renderer.tracer().setSamplesPerFrame(std::min(settings.samplesPerFrame, spp - out.stats.spp));
    out.stats.add(renderer.renderFrame(timeSeconds));
    if (progress) progress(out.stats.spp);
  }
  out.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (renderer.guide()) out.stats.guidingStats = renderer.guide()->stats();
  out.image = renderer.tracer().readImage();
  return out;
}

}  // namespace qlight::session
