#include "engine/render/path_tracer.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "engine/gpu/pass_recorder.h"
#include "shaders/shared/accum_decay.h"
#include "shaders/shared/specialization.h"

namespace qlight::render {

using shared::FrameUniforms;

FrameCounters& FrameCounters::operator+=(const FrameCounters& o) {
  rays += o.rays;
  shadowRays += o.shadowRays;
  paths += o.paths;
  emitterHits += o.emitterHits;
  pathVertices += o.pathVertices;
  invalidSamples += o.invalidSamples;
  coveredVertices += o.coveredVertices;
  return *this;
}

bool tracesInShade(TraceKernel kernel, const gpu::Context& ctx) {
  if (kernel == TraceKernel::Auto)
    return ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  return kernel == TraceKernel::Fused;
}

PathTracer::PathTracer(const gpu::Context& ctx, const RenderSettings& settings)
    : ctx_(ctx),
      begin_(ctx, "pt_begin"),
      queue_(ctx, "pt_queue"),
      variants_(ctx),
      queueState_(ctx, 2 * sizeof(shared::QueueState), "path.queues",
                  VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT),
      frameUniforms_(ctx, sizeof(FrameUniforms), "frame.uniforms", 0, gpu::MemoryUse::HostVisible),
      stats_(ctx, shared::kStatCount * sizeof(uint32_t), "frame.stats"),
      decay_(ctx, "accum_decay") {
  setSettings(settings);
}

void PathTracer::setSettings(const RenderSettings& s) {
  if (s.width == 0 || s.height == 0 || s.width > 16384 || s.height > 16384)
    throw std::invalid_argument("resolution must be 1..16384 in each direction");
  if (s.samplesPerFrame == 0 || s.samplesPerFrame > 4096)
    throw std::invalid_argument("samples per frame must be 1..4096");
  if (s.maxDepth > 1024) throw std::invalid_argument("max depth must be 0..1024");
  if (!(s.exposure > 0.0f) || !std::isfinite(s.exposure))
    throw std::invalid_argument("exposure must be a positive finite number");
  bool resize = !accum_ || accum_->width() != s.width || accum_->height() != s.height;
  if (resize) {
    // The path state is one storage texel buffer of every pixel's paths (texel count
    // limit), each path queue a storage buffer (range limit), all in device memory.
    const uint64_t pixels = uint64_t(s.width) * s.height;
    const std::string what =
        "a " + std::to_string(s.width) + "x" + std::to_string(s.height) + " render";
    ctx_.requireBufferFits(what, pixels * shared::kPathStateTexels * 16, false,
                           pixels * shared::kPathStateTexels);
    ctx_.requireBufferFits(what, pixels * 4, true, 0);    // each path queue
    ctx_.requireBufferFits(what, pixels * 16, false, 0);  // the accumulation image
  }
  settings_ = s;
  if (resize) {
    accum_ = std::make_unique<gpu::Image>(ctx_, s.width, s.height, VK_FORMAT_R32G32B32A32_SFLOAT,
                                          "accumulation");
    uint64_t texels = uint64_t(s.width) * s.height * shared::kPathStateTexels;
    pathsView_.reset();
    paths_ = std::make_unique<gpu::Buffer>(ctx_, texels * 16, "path.state",
                                           VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT);
    pathsView_ = std::make_unique<gpu::BufferView>(ctx_, *paths_, VK_FORMAT_R32G32B32A32_UINT);
    for (int q = 0; q < 2; ++q)
      queueIds_[q] = std::make_unique<gpu::Buffer>(ctx_, uint64_t(s.width) * s.height * 4,
                                                   "path.queue" + std::to_string(q));
  }
  resetAccumulation();
}

shared::GpuCamera gpuCamera(const CameraView& camera, float aspect) {
  shared::GpuCamera c{};
  const glm::vec3 forward = glm::normalize(camera.forward);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  c.position = camera.position;
  c.forward = forward;
  c.right = right;
  c.up = glm::cross(right, forward);
  c.tanHalfFovY = std::tan(0.5f * camera.yfov);
  c.aspect = aspect;
  return c;
}

void PathTracer::resetAccumulation() {
  clearPending_ = true;
  accumulated_ = 0;
  // sampleCounter_ keeps running: restarted accumulations (a moving camera)
  // must not repeat the previous frame's noise pattern.
}

const gpu::ComputePipeline& PathTracer::specialized(const char* shader, const GpuScene& scene,
                                                    const GuideFeatures& guide,
                                                    uint32_t bouncePhase) {
  // Specialization constants of shaders/include/features.glsl.
  std::vector<uint32_t> features = scene.specializationFeatures();
  features[shared::kSpecUseGuiding] = guide.points;
  features[shared::kSpecUseLightLearning] = guide.lightLearning;
  features[shared::kSpecUseDqn] = guide.dqn;
  features[shared::kSpecUseDirectionTrees] = guide.directionTrees;
  features[shared::kSpecUseTdTarget] = guide.tdTarget;
  features[shared::kSpecDqnBins] = guide.dqnBins;
  features[shared::kSpecDqnWidth] = guide.dqnWidth;
  features[shared::kSpecDqnHidden] = guide.dqnHidden;
  features[shared::kSpecDqnOutputs] = guide.dqnOutputs;
  features[shared::kSpecDqnGrid] = guide.dqnGrid;
  features[shared::kSpecBouncePhase] = bouncePhase;
  features[shared::kSpecLearn] = guide.learns;
  features[shared::kSpecTraceInShade] = tracesInShade(settings_.traceKernel, ctx_);
  return variants_.get(shader, features);
}

void PathTracer::setTemporalBlend(float k) {
  if (!(k >= 0.0f && k < 1.0f)) throw std::invalid_argument("temporal blend must be in [0, 1)");
  settings_.temporalBlend = k;
}

void PathTracer::fadeAccumulation(float factor) {
  if (!(factor >= 0.0f && factor <= 1.0f))
    throw std::invalid_argument("fade factor must be in [0, 1]");
  if (factor == 0.0f) return resetAccumulation();
  pendingFade_ *= factor;
  accumulated_ = uint32_t(float(accumulated_) * factor);
}

void PathTracer::recordFrame(gpu::PassRecorder& rec, const GpuScene& scene,
                             const CameraView& camera, const Guide& guide) {
  if (!cameraValid_ || !(camera == lastCamera_)) {
    if (cameraValid_) resetAccumulation();
    lastCamera_ = camera;
    cameraValid_ = true;
  }
  keptOfPrevious_ = clearPending_ ? 0.0f : pendingFade_;
  if (clearPending_) {
    rec.clear("accumulate.clear", *accum_);
    clearPending_ = false;
    pendingFade_ = 1.0f;
  } else if (pendingFade_ < 1.0f) {
    shared::AccumDecayPush push{pendingFade_, settings_.width, settings_.height, 0};
    rec.pass("accumulate.fade", decay_)
        .write(QL_ACCUM_DECAY_BIND_ACCUM, *accum_)
        .push(push)
        .dispatchThreads(settings_.width, settings_.height);
    pendingFade_ = 1.0f;
  }
  rec.fill("stats.clear", stats_, 0);

  FrameUniforms u{};
  u.camera = gpuCamera(camera, float(settings_.width) / float(settings_.height));
  u.resolution = glm::uvec2(settings_.width, settings_.height);
  u.frameIndex = sampleCounter_;
  u.seed = settings_.seed;
  u.maxDepth = settings_.maxDepth;
  u.flags = settings_.russianRoulette ? shared::kFlagRussianRoulette : 0u;
  switch (settings_.estimator) {
    case Estimator::Mis:
      u.flags |= shared::kFlagNee | shared::kFlagEmitterHits | shared::kFlagMis;
      break;
    case Estimator::BsdfOnly:
      u.flags |= shared::kFlagEmitterHits;
      break;
    case Estimator::NeeOnly:
      u.flags |= shared::kFlagNee;
      break;
  }
  u.lightCount = scene.lightCount();
  u.samplesPerFrame = settings_.samplesPerFrame;
  u.sceneCenter = scene.boundsCenter();
  u.sceneRadius = scene.boundsRadius();
  frameUniforms_.upload(ctx_, &u, sizeof(u));

  const uint32_t pathCount = settings_.width * settings_.height;
  // Every path pass binds the scene, the guiding tables, the frame and the path state.
  auto pass = [&](const char* name, const gpu::ComputePipeline& pipeline, uint32_t sample,
                  uint32_t bounce, uint32_t extend) {
    auto p = rec.pass(name, pipeline);
    scene.bind(p);
    guide.bind(p);
    p.read(QL_BIND_FRAME, frameUniforms_)
        .write(QL_BIND_PATH_STATE, *pathsView_)
        .push(shared::TracePush{sample, bounce, extend, pathCount});
    return p;
  };
  // pt_queue makes queue (bounce & 1) current: its dispatch size, and the other one emptied.
  auto switchQueues = [&](uint32_t sample, uint32_t bounce, bool start) {
    rec.pass("path.queue", queue_)
        .write(QL_BIND_QUEUE_STATE, queueState_)
        .push(shared::TracePush{sample, bounce, start ? 1u : 0u, pathCount})
        .dispatch(1);
  };
  auto queued = [&](gpu::PassBuilder p, uint32_t bounce) {
    p.read(QL_BIND_QUEUE_IN, *queueIds_[bounce & 1])
        .write(QL_BIND_QUEUE_STATE, queueState_)
        .dispatchIndirect(queueState_, (bounce & 1) * sizeof(shared::QueueState) +
                                           offsetof(shared::QueueState, groupsX));
  };
  const GuideFeatures features = guide.features();
  const bool fused = tracesInShade(settings_.traceKernel, ctx_);
  const gpu::ComputePipeline* trace = fused ? nullptr : &specialized("pt_trace", scene, features);
  // The shade pass per bounce phase (camera hits, bounce 1, later): each leaves out the
  // others' steps, which lavapipe would otherwise run masked at every bounce.
  const gpu::ComputePipeline* shadeByPhase[3];
  for (uint32_t phase = 0; phase < 3; ++phase)
    shadeByPhase[phase] =
        &specialized("pt_shade", scene, features, shared::kBouncePhaseCamera + phase);
  const gpu::ComputePipeline& end = specialized("pt_end", scene, features);
  // Wavefront: begin, then per bounce trace (extension rays) and shade (which traces its
  // shadow rays) over the live paths only, end. Fused, the shade pass traces the extension
  // rays and its camera-hit pipeline starts the paths (no begin pass).
  for (uint32_t s = 0; s < settings_.samplesPerFrame; ++s) {
    if (!fused)
      pass("path.begin", begin_, s, 0, 0)
          .write(QL_BIND_QUEUE_OUT, *queueIds_[0])
          .dispatchThreads(pathCount);
    switchQueues(s, 0, true);
    for (uint32_t bounce = 0; bounce <= settings_.maxDepth; ++bounce) {
      if (bounce > 0) switchQueues(s, bounce, false);
      if (trace) queued(pass("path.trace", *trace, s, bounce, 1), bounce);
      const gpu::ComputePipeline& shade =
          *shadeByPhase[shared::bouncePhaseOf(bounce) - shared::kBouncePhaseCamera];
      queued(pass("path.shade", shade, s, bounce, 0)
                 .write(QL_BIND_QUEUE_OUT, *queueIds_[(bounce + 1) & 1]),
             bounce);
    }
    pass("path.end", end, s, 0, 0)
        .write(QL_BIND_ACCUM, *accum_)
        .write(QL_BIND_STATS, stats_)
        .dispatchThreads(pathCount);
  }
  sampleCounter_ += settings_.samplesPerFrame;
  accumulated_ += settings_.samplesPerFrame;
}

FrameCounters PathTracer::collectCounters() {
  auto raw = stats_.read<uint32_t>(ctx_);
  FrameCounters c;
  c.rays = raw[shared::kStatRays];
  c.shadowRays = raw[shared::kStatShadowRays];
  c.paths = raw[shared::kStatPaths];
  c.emitterHits = raw[shared::kStatEmitterHits];
  c.pathVertices = raw[shared::kStatPathVertices];
  c.invalidSamples = raw[shared::kStatInvalidSamples];
  c.coveredVertices = raw[shared::kStatCoveredVertices];
  return c;
}

image::LinearImage PathTracer::readImage() const {
  image::LinearImage img;
  img.width = settings_.width;
  img.height = settings_.height;
  img.rgba = accum_->readFloats(ctx_);
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    float n = img.rgba[i + 3];
    for (int c = 0; c < 3; ++c) img.rgba[i + c] = n > 0.0f ? img.rgba[i + c] / n : 0.0f;
    img.rgba[i + 3] = 1.0f;
  }
  return img;
}

}  // namespace qlight::render
