#include "game/bench/bench_methods.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include "engine/session/renderer.h"

namespace qlight::game::bench {
namespace {

struct MethodState {
  MethodResult result;
  std::unique_ptr<session::Renderer> renderer;
  uint32_t nextCheckpoint = 1;
  bool frozen = false;
};

void measure(MethodState& m, const image::LinearImage& reference) {
  m.result.finalImage = m.renderer->tracer().readImage();
  m.result.checkpoints.push_back(
      {m.result.spp, m.result.seconds, relativeMse(m.result.finalImage, reference)});
}

// A pipeline is built at its first dispatch (seconds on lavapipe for the deep Q variants) and
// kept in the Context's PipelineLibrary: one untimed frame of each method at a tiny size, by
// renderers that are then dropped, keeps building out of the timed frames.
void warmUpPipelines(const gpu::Context& ctx, const scene::SceneAsset& asset,
                     const std::vector<MethodSpec>& methods, const render::RenderSettings& render) {
  render::RenderSettings tiny = render;
  tiny.width = tiny.height = 8;
  for (const MethodSpec& m : methods)
    session::Renderer(ctx, asset, tiny, m.guiding).renderFrame(0.0f);
}

}  // namespace

std::vector<MethodSpec> benchMethods(const guiding::GuidingSettings& base) {
  guiding::GuidingSettings off = base, q = base, light = base, dqn = base;
  off.enabled = false;
  q.lightLearning = false;
  light.lightLearning = true;
  dqn.method = guiding::GuideMethod::Dqn;
  return {{"unguided", "unguided (MIS)", off, 0.0},
          {"guided", "Q-guided", q, 0.0},
          {"guided_light", "Q-guided + learned light selection", light, 0.0},
          {"guided_frozen", "Q-guided, learning frozen after warm-up", q, 0.25},
          {"guided_dqn", "deep Q (network trained on the GPU)", dqn, 0.0}};
}

std::vector<MethodResult> runMethods(const gpu::Context& ctx, const scene::SceneAsset& asset,
                                     const std::vector<MethodSpec>& methods,
                                     const MethodRunSettings& settings,
                                     const image::LinearImage& reference, ProgressBar& progress,
                                     double progressBase, const std::string& sceneName) {
  using Clock = std::chrono::steady_clock;
  warmUpPipelines(ctx, asset, methods, settings.render);
  std::vector<MethodState> states(methods.size());
  for (size_t i = 0; i < methods.size(); ++i) {
    states[i].result.spec = methods[i];
    // Point generation happens before the first frame and is not counted: it is a
    // one-off cost of a scene, reported apart (point_generation_seconds in render stats).
    states[i].renderer =
        std::make_unique<session::Renderer>(ctx, asset, settings.render, methods[i].guiding);
    states[i].nextCheckpoint = settings.render.samplesPerFrame;
  }
  const double budget = settings.budgetSeconds;
  for (bool running = true; running;) {
    running = false;
    for (MethodState& m : states) {
      MethodResult& r = m.result;
      if (r.seconds >= budget) continue;
      running = true;
      if (r.spec.freezeAfterShare > 0 && !m.frozen &&
          r.seconds >= r.spec.freezeAfterShare * budget) {
        guiding::GuidingSettings frozen = r.spec.guiding;
        frozen.learn = false;
        m.renderer->setGuiding(frozen);
        m.frozen = true;
      }
      auto start = Clock::now();
      session::FrameResult frame = m.renderer->renderFrame(0.0f);
      double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      r.seconds += seconds;
      r.spp += frame.samples;
      ++r.frames;
      r.rays += frame.counters.rays;
      r.frameSeconds.push_back(seconds);
      r.emitterHitShare.push_back(frame.emitterHitShare());
      r.meanPathLength.push_back(frame.meanPathLength());
      for (auto& [name, ms] : frame.gpuMs) r.gpuMsTotal[name] += ms;
      if (r.spp >= m.nextCheckpoint || r.seconds >= budget) {
        measure(m, reference);
        m.nextCheckpoint = std::max(r.spp + 1, uint32_t(float(r.spp) * settings.checkpointGrowth));
      }
    }
    double done = 0;
    for (const MethodState& m : states) done += std::min(m.result.seconds, budget);
    progress.update(progressBase + done, sceneName + ": methods");
  }
  std::vector<MethodResult> results;
  for (MethodState& m : states) {
    m.result.sceneLights = m.renderer->scene().lightCount();
    if (const guiding::DqnGuide* network = m.renderer->dqnGuide()) {
      m.result.guideMemoryBytes = network->memoryBytes();
    } else if (const guiding::QGuide* guide = m.renderer->guide();
               guide && m.result.spec.guiding.enabled) {
      m.result.guideMemoryBytes = guide->memoryBytes();
      m.result.points = guide->stats().points;
    }
    results.push_back(std::move(m.result));
  }
  return results;
}

}  // namespace qlight::game::bench
