// The path tracing passes, as a wavefront per sample: begin (camera rays),
// then per bounce trace (the pending shadow ray and the extension ray) and
// shade over a GPU work queue of live paths (indirect dispatch), a last trace
// for the final shadow rays, end (into the accumulation image and the frame's
// counters). Accumulation runs while nothing changes and restarts when the
// camera, the scene or a setting does (or fades, with temporal blending).
#pragma once
#include <map>
#include <memory>
#include <string>

#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/image.h"
#include "engine/image/image_io.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/guide.h"
#include "engine/render/pipeline_variants.h"
#include "engine/render/render_settings.h"
#include "shaders/shared/scene_types.h"
#include "shaders/shared/specialization.h"

namespace qlight::render {

// The camera as the shaders build primary rays from it (pt_begin.comp, gbuffer.comp).
shared::GpuCamera gpuCamera(const CameraView& camera, float aspect);

struct FrameCounters {
  uint64_t rays = 0, shadowRays = 0, paths = 0, emitterHits = 0, pathVertices = 0,
           invalidSamples = 0, coveredVertices = 0;
  FrameCounters& operator+=(const FrameCounters& o);
};

// Whether `kernel` fuses the extension rays' trace into the shade pass on this device.
bool tracesInShade(TraceKernel kernel, const gpu::Context& ctx);

class PathTracer {
 public:
  PathTracer(const gpu::Context& ctx, const RenderSettings& settings);

  // Changes settings; restarts accumulation (and reallocates on a new resolution).
  void setSettings(const RenderSettings& settings);
  const RenderSettings& settings() const { return settings_; }
  void resetAccumulation();
  // Keeps the accumulated samples but weights them by `factor` (0..1) before
  // the next frame's: an exponentially fading history for animated scenes.
  void fadeAccumulation(float factor);
  // The batch size alone does not change the image: accumulation goes on.
  void setSamplesPerFrame(uint32_t n) { settings_.samplesPerFrame = n; }
  // Nor does the weight a fade will keep (settings.temporalBlend, in [0, 1)).
  void setTemporalBlend(float k);
  uint32_t accumulatedSamples() const { return accumulated_; }
  // What the last recorded frame kept of the accumulation before it: 0 when it restarted
  // (the camera or the scene moved), the fade factor with temporal blending, else 1.
  float keptOfPrevious() const { return keptOfPrevious_; }

  // Records settings.samplesPerFrame samples of `scene` seen from `camera`.
  // The camera moving restarts accumulation. `guide` binds the learned
  // distributions (engine/guiding; its null guide for unguided paths).
  void recordFrame(gpu::PassRecorder& recorder, const GpuScene& scene, const CameraView& camera,
                   const Guide& guide);
  // After the frame's fence: its counters (the stats buffer is cleared for the next frame).
  FrameCounters collectCounters();

  const gpu::Image& accumulation() const { return *accum_; }
  // Mean radiance per pixel (waits for the GPU).
  image::LinearImage readImage() const;

 private:
  const gpu::Context& ctx_;
  RenderSettings settings_;
  // The wavefront passes (shaders/pt_*.comp) and the path state between them.
  gpu::ComputePipeline begin_, queue_;
  // The path passes specialized per feature set (textures, guiding, light learning,
  // non-triangle lights, learning, ...) and, for pt_shade, bounce phase (kBouncePhase*).
  const gpu::ComputePipeline& specialized(const char* shader, const GpuScene& scene,
                                          const GuideFeatures& guide,
                                          uint32_t bouncePhase = shared::kBouncePhaseAny);
  PipelineVariants variants_;
  std::unique_ptr<gpu::Buffer> paths_;
  std::unique_ptr<gpu::BufferView> pathsView_;
  std::unique_ptr<gpu::Buffer> queueIds_[2];
  gpu::Buffer queueState_;  // shared::QueueState[2]: counts and indirect dispatch sizes
  std::unique_ptr<gpu::Image> accum_;
  gpu::Buffer frameUniforms_;
  gpu::Buffer stats_;
  CameraView lastCamera_;
  bool cameraValid_ = false;
  bool clearPending_ = true;
  float pendingFade_ = 1.0f;
  float keptOfPrevious_ = 0.0f;
  gpu::ComputePipeline decay_;
  uint32_t accumulated_ = 0;
  uint32_t sampleCounter_ = 0;  // seeds: never reused within one accumulation
};

}  // namespace qlight::render
