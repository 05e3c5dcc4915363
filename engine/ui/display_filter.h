// What the window shows while the camera moves, made better than a fresh 1-spp frame, for
// display only (the accumulation, PFM/EXR outputs and every measurement stay unfiltered):
// temporal reuse of the last displayed frame by reprojection with a disocclusion test, and
// an optional edge-aware a-trous denoiser guided by the primary hits' normals, distances and
// base colours. Passes: gbuffer (one primary ray per pixel centre), temporal_reuse, then
// `iterations` x atrous. output() has the accumulation's format (rgb sum, a weight), so the
// display pass reads it as it reads the accumulation.
#pragma once
#include <map>
#include <memory>

#include "engine/gpu/buffer.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/image.h"
#include "engine/gpu/pass_recorder.h"
#include "engine/image/image_io.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/pipeline_variants.h"
#include "engine/render/scene_draw.h"

namespace qlight::ui {

struct DisplayFilterSettings {
  bool reuseHistory = true;  // reproject the last frame when the accumulation restarts
  float historyFrames = 8;   // most frames of weight a reprojected history keeps
  bool denoise = false;
  float strength = 1.0f;      // the a-trous colour tolerance (larger: smoother, blurrier)
  int iterations = 4;         // a-trous iterations: the kernel reaches 2^(iterations+1) pixels
  float maxLuminance = 4.0f;  // fireflies are scaled down to this first (the window: 4 / exposure)
  bool active() const { return reuseHistory || denoise; }
};

class DisplayFilter {
 public:
  explicit DisplayFilter(const gpu::Context& ctx);

  // Records the passes for this frame. `keptOfPrevious` is the tracer's (0: its accumulation
  // restarted this frame); `camera` is what it traced.
  void record(gpu::PassRecorder& recorder, const render::GpuScene& scene,
              const gpu::Image& accumulation, float keptOfPrevious,
              const render::CameraView& camera, const DisplayFilterSettings& settings);
  const gpu::Image& output() const;
  // The output's mean radiance per pixel (waits for the GPU): the headless demo's filtered
  // frames when the user asks for them.
  image::LinearImage readOutput() const;

 private:
  void resize(uint32_t width, uint32_t height);

  const gpu::Context& ctx_;
  render::PipelineVariants gbufferPipelines_;  // the G-buffer pass, per scene features
  gpu::ComputePipeline temporal_, atrous_;
  gpu::Buffer uniforms_;
  // Ping-pong pairs: this frame's and the last frame's (index current_).
  std::unique_ptr<gpu::Image> gbuffers_[2], outputs_[2], filtered_[2];
  std::unique_ptr<gpu::Image> albedo_, history_;
  uint32_t current_ = 0, lastFiltered_ = 0;
  bool denoisedLast_ = false;
  bool hasPrevious_ = false;
  render::CameraView previousCamera_;
};

}  // namespace qlight::ui
