#include "engine/session/renderer.h"

#include <chrono>

#include "engine/gpu/pass_recorder.h"

namespace qlight::session {
namespace {

float aspectOf(const render::RenderSettings& s, float aspect) {
  return aspect > 0.0f ? aspect : float(s.width) / float(s.height);
}

}  // namespace

Renderer::Renderer(const gpu::Context& ctx, const scene::SceneAsset& asset,
                   const render::RenderSettings& settings, const guiding::GuidingSettings& guiding,
                   float aspect)
    : ctx_(ctx),
      world_(asset, aspectOf(settings, aspect)),
      scene_(ctx, asset),
      tracer_(ctx, settings),
      nullGuide_(ctx),
      timer_(ctx),
      lightMotion_(asset) {
  scene_.update(world_.draw());
  lightMotion_.update(world_.draw(), scene_.boundsRadius());
  // The frame's resources live as long as the renderer; each frame only fills them in.
  world_.registry().setResource<FrameView>();
  world_.registry().setResource<FrameRecording>();
  registerSystems();
  if (guiding.enabled) setGuiding(guiding);
}

void Renderer::registerSystems() {
  using ecs::Phase;
  ecs::Scheduler& s = world_.scheduler();
  s.add("scene.upload")
      .phase(Phase::Upload)
      .reads<render::SceneDraw>()
      .writes<render::GpuScene, render::PathTracer>()
      .run([this](ecs::Registry&) { uploadScene(); });
  s.add("guide.points")
      .phase(Phase::Upload)
      .reads<guiding::CachePoint>()
      .writes<guiding::CachePointSet>()
      .run([this](ecs::Registry& r) {
        if (dqnActive_)
          dqnGuide_->upload();
        else if (qGuide_)
          qGuide_->uploadPoints(r);
      });
  // The shade pass writes the frame's learning targets into the tables' sums.
  s.add("path.trace")
      .phase(Phase::Trace)
      .reads<FrameView, FrameRecording, render::GpuScene, guiding::CachePointSet>()
      .writes<render::PathTracer, guiding::LearnedTables>()
      .run([this](ecs::Registry& r) {
        tracer_.recordFrame(*r.resource<FrameRecording>().recorder, scene_,
                            r.resource<FrameView>().camera, activeGuide());
      });
  s.add("guide.learn")
      .phase(Phase::Learn)
      .reads<FrameRecording>()
      .writes<guiding::LearnedTables>()
      .run([this](ecs::Registry& r) {
        gpu::PassRecorder& recorder = *r.resource<FrameRecording>().recorder;
        if (dqnActive_)
          dqnGuide_->recordLearning(recorder);
        else if (qGuide_)
          qGuide_->recordLearning(recorder);
      });
  s.compile();
}

void Renderer::uploadScene() {
  if (!world_.moved()) return;
  // Moving lights and objects change the image: accumulation restarts (or fades, with
  // temporal blending), while the learned distributions persist and follow the lights.
  scene_.update(world_.draw());
  const float lightMoved = lightMotion_.update(world_.draw(), scene_.boundsRadius());
  if (qGuide_) qGuide_->noteLightMotion(lightMoved);
  float blend = tracer_.settings().temporalBlend;
  if (blend > 0.0f)
    tracer_.fadeAccumulation(blend);
  else
    tracer_.resetAccumulation();
}

const render::Guide& Renderer::activeGuide() const {
  if (dqnActive_) return *dqnGuide_;
  if (qGuide_) return *qGuide_;
  return nullGuide_;
}

void Renderer::update(float time, std::optional<render::CameraView> camera) {
  world_.advance(time);  // simulate, extract
  world_.registry().resource<FrameView>().camera = camera.value_or(world_.camera());
  scheduler().runPhase(world_.registry(), ecs::Phase::Upload);
}

void Renderer::record(VkCommandBuffer cmd) {
  timer_.reset(cmd);
  gpu::PassRecorder recorder(ctx_, cmd, &timer_);
  ecs::Registry& registry = world_.registry();
  FrameRecording& recording = registry.resource<FrameRecording>();
  recording.recorder = &recorder;
  for (ecs::Phase phase : {ecs::Phase::Trace, ecs::Phase::Learn, ecs::Phase::Present})
    scheduler().runPhase(registry, phase);
  recorder.finish();
  recording.recorder = nullptr;  // the recorder ends here
}

FrameResult Renderer::collect() {
  FrameResult r;
  r.counters = tracer_.collectCounters();
  r.gpuMs = timer_.collect(ctx_);
  r.samples = tracer_.settings().samplesPerFrame;
  if (qGuide_) qGuide_->acceptSpawns(world_.registry());  // they upload with the next frame
  return r;
}

FrameResult Renderer::renderFrame(float time, std::optional<render::CameraView> camera) {
  update(time, camera);
  ctx_.submitAndWait([&](VkCommandBuffer cmd) { record(cmd); });
  return collect();
}

void Renderer::setGuiding(const guiding::GuidingSettings& requested, bool regenerate) {
  const render::RenderSettings& r = tracer_.settings();
  const uint64_t paths = uint64_t(r.width) * r.height * r.samplesPerFrame;
  dqnActive_ = requested.enabled && requested.method == guiding::GuideMethod::Dqn;
  if (dqnActive_) {
    if (dqnGuide_ && dqnGuide_->sameShape(requested))
      dqnGuide_->setSettings(requested);
    else
      dqnGuide_ = std::make_unique<guiding::DqnGuide>(ctx_, requested, scene_, paths);
    return;
  }
  guiding::GuidingSettings settings = requested;
  // An automatic budget is sized once, for the frame the points are made for: a later
  // render-size change does not regenerate the points unless asked to.
  if (requested.pointBudget == 0 && qGuide_ && !regenerate)
    settings.pointBudget = qGuide_->settings().pointBudget;
  else
    settings.pointBudget = guiding::resolvedPointBudget(requested, paths);
  if (!qGuide_) {
    if (!settings.enabled) return;
    auto start = std::chrono::steady_clock::now();
    qGuide_ = std::make_unique<guiding::QGuide>(ctx_, settings);
    qGuide_->generatePoints(world_.registry(), scene_);
    pointGenerationSeconds_ =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return;
  }
  qGuide_->setSettings(settings);
  if (regenerate || qGuide_->needsPoints()) qGuide_->generatePoints(world_.registry(), scene_);
}

RenderStats Renderer::newStats() const {
  RenderStats s;
  s.width = tracer_.settings().width;
  s.height = tracer_.settings().height;
  s.device = ctx_.deviceName();
  s.traceInShade = render::tracesInShade(tracer_.settings().traceKernel, ctx_);
  s.lights = scene_.lightCount();
  s.fallbackSky = scene_.usesFallbackSky();
  s.glowMapsOnly = scene_.glowMapsOnly();
  s.environmentLight = scene_.hasEnvironment();
  s.guided = guided();
  s.deepQ = s.guided && dqnActive_;
  s.pointGenerationSeconds = pointGenerationSeconds_;
  s.triangles = scene_.triangleCount();
  s.sceneGpuBytes = scene_.memoryBytes();
  s.blasBuildSeconds = scene_.blasBuildSeconds();
  s.sceneBuildSeconds = scene_.buildSeconds();
  return s;
}

}  // namespace qlight::session
