// One frame, one owner: the scene world, its GPU copy, the path tracer, the
// guide and the GPU timer, with every step of the frame a system in the
// scheduler's fixed phases:
//
//   simulate   animation, transforms                     (SceneWorld)
//   extract    what the renderer draws                    (SceneWorld)
//   upload     scene and cache points to the GPU; accumulation restarts or fades
//              when something moved
//   trace      the path tracing passes                    (PathTracer)
//   learn      the guide's updates and CDFs               (QGuide)
//   present    the caller's display passes (the window's tonemap), if any
//
// and, after the frame's fence, collect(): counters, GPU times, spawned points.
// The offline render, the headless demo, the window and the tests only choose
// how to submit and present.
#pragma once
#include <memory>
#include <optional>

#include "engine/gpu/context.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/guiding/dqn_guide.h"
#include "engine/guiding/null_guide.h"
#include "engine/guiding/q_guide.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/path_tracer.h"
#include "engine/session/light_motion.h"
#include "engine/session/render_stats.h"
#include "engine/session/scene_world.h"

namespace qlight::session {

// Registry resources of the frame being recorded, for the trace, learn and present systems.
struct FrameView {
  render::CameraView camera;
};
struct FrameRecording {
  gpu::PassRecorder* recorder = nullptr;
};

class Renderer {
 public:
  // `aspect` frames the default camera (scenes without one); 0: the render size's.
  // Guiding starts as `guiding` says (points generated now when it is on).
  Renderer(const gpu::Context& ctx, const scene::SceneAsset& asset,
           const render::RenderSettings& settings, const guiding::GuidingSettings& guiding,
           float aspect = 0.0f);
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Simulate, extract and upload at scene time `time`, seen from `camera` (by default
  // the scene's camera at that time).
  void update(float time, std::optional<render::CameraView> camera = {});
  // Trace, learn and present into `cmd` (GPU timestamps start over with it).
  void record(VkCommandBuffer cmd);
  // After the frame's fence.
  FrameResult collect();
  // update + record + submit and wait + collect: a frame for the offline render,
  // the headless demo and the tests.
  FrameResult renderFrame(float time, std::optional<render::CameraView> camera = {});

  // New guiding settings (the window's panel): strata changes reset the tables, point
  // settings or `regenerate` make new points; switching guiding on the first time
  // creates the guide. Guiding never biases the image, so accumulation goes on.
  void setGuiding(const guiding::GuidingSettings& settings, bool regenerate = false);
  // Null when guiding was never switched on.
  const guiding::QGuide* guide() const { return qGuide_.get(); }
  guiding::QGuide* guide() { return qGuide_.get(); }
  // The deep Q guide while it is the method in use, else null.
  const guiding::DqnGuide* dqnGuide() const { return dqnActive_ ? dqnGuide_.get() : nullptr; }
  guiding::DqnGuide* dqnGuide() { return dqnActive_ ? dqnGuide_.get() : nullptr; }
  bool guided() const { return dqnActive_ || (qGuide_ && qGuide_->settings().enabled); }
  double pointGenerationSeconds() const { return pointGenerationSeconds_; }

  SceneWorld& world() { return world_; }
  const SceneWorld& world() const { return world_; }
  ecs::Scheduler& scheduler() { return world_.scheduler(); }
  const render::GpuScene& scene() const { return scene_; }
  render::PathTracer& tracer() { return tracer_; }
  const render::PathTracer& tracer() const { return tracer_; }
  gpu::GpuTimer& timer() { return timer_; }
  const gpu::Context& context() const { return ctx_; }
  // Statistics of a run of frames with this renderer's fixed facts filled in.
  RenderStats newStats() const;

 private:
  void registerSystems();
  void uploadScene();
  const render::Guide& activeGuide() const;

  const gpu::Context& ctx_;
  SceneWorld world_;
  render::GpuScene scene_;
  render::PathTracer tracer_;
  guiding::NullGuide nullGuide_;
  std::unique_ptr<guiding::QGuide> qGuide_;
  std::unique_ptr<guiding::DqnGuide> dqnGuide_;
  bool dqnActive_ = false;  // the deep Q guide is the method in use
  gpu::GpuTimer timer_;
  LightMotion lightMotion_;  // how far lights moved: what tracking forgets by
  double pointGenerationSeconds_ = 0;
};

}  // namespace qlight::session
