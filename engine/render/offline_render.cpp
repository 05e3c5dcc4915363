#include "engine/render/offline_render.h"

#include <algorithm>
#include <chrono>

#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/pass_recorder.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/scene_extract.h"

namespace qlight::render {

OfflineRender renderScene(const gpu::Context& ctx, const scene::SceneAsset& asset,
                          const RenderSettings& settings, uint32_t spp, float timeSeconds) {
  PosedScene posed = poseScene(asset, timeSeconds, float(settings.width) / float(settings.height));
  GpuScene gpuScene(ctx, asset);
  gpuScene.update(posed.draw);
  PathTracer tracer(ctx, settings);
  gpu::GpuTimer timer(ctx);

  OfflineRender out;
  RenderStats& st = out.stats;
  st.width = settings.width;
  st.height = settings.height;
  st.device = ctx.deviceName();
  st.lights = gpuScene.lightCount();
  st.fallbackSky = gpuScene.usesFallbackSky();
  auto start = std::chrono::steady_clock::now();
  uint32_t done = 0;
  while (done < spp) {
    uint32_t batch = std::min(settings.samplesPerFrame, spp - done);
    tracer.setSamplesPerFrame(batch);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
      timer.reset(cmd);
      gpu::PassRecorder rec(ctx, cmd, &timer);
      tracer.recordFrame(rec, gpuScene, posed.camera);
      rec.finish();
    });
    st.counters += tracer.collectCounters();
    for (auto& [name, ms] : timer.collect(ctx)) st.gpuMs[name] += ms;
    done += batch;
    ++st.frames;
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  st.spp = done;
  out.image = tracer.readImage();
  return out;
}

}  // namespace qlight::render
