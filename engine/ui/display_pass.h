// The compute pass that turns the path tracer's accumulation (rgba32f: rgb =
// sum of radiance, a = sample count) into a displayable RGBA8 image: mean,
// exposure, tonemap, sRGB encoding (shaders/display.comp).
#pragma once
#include <memory>

#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/image.h"
#include "engine/gpu/pass_recorder.h"
#include "shaders/shared/tonemap.h"

namespace qlight::ui {

struct DisplaySettings {
  float exposure = 1.0f;
  uint32_t tonemap = shared::kTonemapAces;  // or shared::kTonemapClamp
  bool encodeSrgb = true;                   // false when the swapchain format encodes sRGB itself
};

class DisplayPass {
 public:
  explicit DisplayPass(const gpu::Context& ctx);

  // Records the pass "display": reads `accumulation`, writes output(), which
  // follows the accumulation's size (reallocated when it changes, so no frame
  // that uses the old one may still be in flight).
  void record(gpu::PassRecorder& recorder, const gpu::Image& accumulation,
              const DisplaySettings& settings);
  const gpu::Image& output() const { return *output_; }

 private:
  const gpu::Context& ctx_;
  gpu::ComputePipeline pipeline_;
  std::unique_ptr<gpu::Image> output_;
};

}  // namespace qlight::ui
