#include "engine/ui/display_filter.h"

#include "engine/render/path_tracer.h"
#include "engine/ui/display_filter_types.h"

namespace qlight::ui {

DisplayFilter::DisplayFilter(const gpu::Context& ctx)
    : ctx_(ctx),
      gbufferPipelines_(ctx),
      temporal_(ctx, "temporal_reuse"),
      atrous_(ctx, "atrous"),
      uniforms_(ctx, sizeof(shared::FilterUniforms), "filter.uniforms",
                VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryUse::HostVisible) {}

void DisplayFilter::resize(uint32_t width, uint32_t height) {
  auto image = [&](const char* name) {
    return std::make_unique<gpu::Image>(ctx_, width, height, VK_FORMAT_R32G32B32A32_SFLOAT, name);
  };
  for (int i = 0; i < 2; ++i) {
    gbuffers_[i] = image("filter.gbuffer");
    outputs_[i] = image("filter.output");
    filtered_[i] = image("filter.denoised");
  }
  albedo_ = image("filter.albedo");
  history_ = image("filter.history");
  hasPrevious_ = false;  // nothing to reproject from at the new size
}

void DisplayFilter::record(gpu::PassRecorder& rec, const render::GpuScene& scene,
                           const gpu::Image& accumulation, float keptOfPrevious,
                           const render::CameraView& camera,
                           const DisplayFilterSettings& settings) {
  const uint32_t w = accumulation.width(), h = accumulation.height();
  if (!history_ || history_->width() != w || history_->height() != h) {
    resize(w, h);
    for (const auto* set : {&gbuffers_, &outputs_, &filtered_})
      for (const auto& img : *set) rec.clear("filter.clear", *img);
    rec.clear("filter.clear", *albedo_);
    rec.clear("filter.clear", *history_);
  }
  const uint32_t now = current_, before = 1 - current_;
  const float aspect = float(w) / float(h);
  shared::FilterUniforms u{};
  u.camera = render::gpuCamera(camera, aspect);
  u.previousCamera = render::gpuCamera(hasPrevious_ ? previousCamera_ : camera, aspect);
  u.restarted = keptOfPrevious == 0.0f || !hasPrevious_ ? 1u : 0u;
  u.reproject = settings.reuseHistory && hasPrevious_ ? 1u : 0u;
  // While the accumulation goes on, the history it started from fades (faster with temporal
  // blending, as the accumulation does), so a still image converges to the accumulation.
  u.historyKeep = 0.8f * keptOfPrevious;
  u.historyMax = settings.historyFrames;
  uniforms_.upload(ctx_, &u, sizeof(u));

  // Specialized on the scene like the path passes: traversal's alpha test, textures.
  gpu::PassBuilder gb =
      rec.pass("filter.gbuffer", gbufferPipelines_.get("gbuffer", scene.specializationFeatures()));
  scene.bindSurfaces(gb);
  gb.read(QL_FILTER_BIND_UNIFORMS, uniforms_)
      .write(QL_FILTER_BIND_GBUFFER, *gbuffers_[now])
      .write(QL_FILTER_BIND_ALBEDO, *albedo_)
      .dispatchThreads(w, h);
  rec.pass("filter.temporal", temporal_)
      .read(QL_FILTER_BIND_UNIFORMS, uniforms_)
      .read(QL_FILTER_BIND_ACCUM, accumulation)
      .read(QL_FILTER_BIND_GBUFFER, *gbuffers_[now])
      .read(QL_FILTER_BIND_PREV_GBUFFER, *gbuffers_[before])
      .read(QL_FILTER_BIND_PREV_OUTPUT, *outputs_[before])
      .write(QL_FILTER_BIND_HISTORY, *history_)
      .write(QL_FILTER_BIND_OUTPUT, *outputs_[now])
      .dispatchThreads(w, h);
  denoisedLast_ = settings.denoise && settings.iterations > 0;
  if (denoisedLast_) {
    const gpu::Image* input = outputs_[now].get();
    for (int i = 0; i < settings.iterations; ++i) {
      const uint32_t target = uint32_t(i % 2);
      shared::AtrousPush push{1 << i, settings.strength, i == 0 ? 1u : 0u,
                              i + 1 == settings.iterations ? 1u : 0u, settings.maxLuminance};
      rec.pass("filter.atrous", atrous_)
          .read(QL_ATROUS_BIND_INPUT, *input)
          .write(QL_ATROUS_BIND_OUTPUT, *filtered_[target])
          .read(QL_FILTER_BIND_GBUFFER, *gbuffers_[now])
          .read(QL_FILTER_BIND_ALBEDO, *albedo_)
          .push(push)
          .dispatchThreads(w, h);
      input = filtered_[target].get();
      lastFiltered_ = target;
    }
  }
  previousCamera_ = camera;
  hasPrevious_ = true;
  current_ = before;  // this frame's images are the next frame's previous ones
}

const gpu::Image& DisplayFilter::output() const {
  // record() flipped current_: the frame just recorded is in 1 - current_.
  return denoisedLast_ ? *filtered_[lastFiltered_] : *outputs_[1 - current_];
}

image::LinearImage DisplayFilter::readOutput() const {
  const gpu::Image& sums = output();
  image::LinearImage img;
  img.width = sums.width();
  img.height = sums.height();
  img.rgba = sums.readFloats(ctx_);
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    const float n = img.rgba[i + 3];
    for (int c = 0; c < 3; ++c) img.rgba[i + c] = n > 0.0f ? img.rgba[i + c] / n : 0.0f;
    img.rgba[i + 3] = 1.0f;
  }
  return img;
}

}  // namespace qlight::ui
