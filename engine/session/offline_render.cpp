#include "engine/session/offline_render.h"

#include <algorithm>
#include <chrono>

#include "engine/ecs/registry.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/pass_recorder.h"
#include "engine/render/gpu_scene.h"
#include "engine/session/scene_world.h"

namespace qlight::render {

guiding::GuidingSettings disabledGuiding() {
  guiding::GuidingSettings g;
  g.enabled = false;
  return g;
}

OfflineRender renderScene(const gpu::Context& ctx, const scene::SceneAsset& asset,
                          const RenderSettings& settings, uint32_t spp, float timeSeconds,
                          const guiding::GuidingSettings& guidingSettings) {
  using Clock = std::chrono::steady_clock;
  session::SceneWorld world(asset, float(settings.width) / float(settings.height));
  world.advance(timeSeconds);
  const CameraView camera = world.camera();
  GpuScene gpuScene(ctx, asset);
  gpuScene.update(world.draw());
  PathTracer tracer(ctx, settings);
  gpu::GpuTimer timer(ctx);

  OfflineRender out;
  RenderStats& st = out.stats;
  ecs::Registry& registry = world.registry();  // the cache points join the scene's entities
  std::unique_ptr<guiding::QGuiding> guiding;
  if (guidingSettings.enabled) {
    auto t0 = Clock::now();
    guiding = std::make_unique<guiding::QGuiding>(ctx, guidingSettings);
    guiding->generatePoints(registry, gpuScene);
    st.pointGenerationSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    st.guided = true;
  }
  st.width = settings.width;
  st.height = settings.height;
  st.device = ctx.deviceName();
  st.lights = gpuScene.lightCount();
  st.fallbackSky = gpuScene.usesFallbackSky();
  auto start = Clock::now();
  uint32_t done = 0;
  while (done < spp) {
    uint32_t batch = std::min(settings.samplesPerFrame, spp - done);
    tracer.setSamplesPerFrame(batch);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
      timer.reset(cmd);
      gpu::PassRecorder rec(ctx, cmd, &timer);
      tracer.recordFrame(rec, gpuScene, camera, guiding ? guiding->binder() : GuidingBinder{});
      if (guiding) guiding->recordLearning(rec);
      rec.finish();
    });
    if (guiding) guiding->afterFrame(registry);
    FrameCounters c = tracer.collectCounters();
    double paths = double(std::max<uint64_t>(c.paths, 1));
    st.emitterHitShareByFrame.push_back(double(c.emitterHits) / paths);
    st.pathLengthByFrame.push_back(double(c.pathVertices) / paths);
    st.counters += c;
    for (auto& [name, ms] : timer.collect(ctx)) st.gpuMs[name] += ms;
    done += batch;
    ++st.frames;
  }
  st.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  st.spp = done;
  if (guiding) st.guidingStats = guiding->stats();
  out.image = tracer.readImage();
  return out;
}

}  // namespace qlight::render
