#include "engine/ui/display_pass.h"

#include "engine/ui/display_types.h"

namespace qlight::ui {

DisplayPass::DisplayPass(const gpu::Context& ctx) : ctx_(ctx), pipeline_(ctx, "display") {}

void DisplayPass::record(gpu::PassRecorder& recorder, const gpu::Image& accumulation,
                         const DisplaySettings& settings) {
  uint32_t w = accumulation.width(), h = accumulation.height();
  if (!output_ || output_->width() != w || output_->height() != h)
    output_ = std::make_unique<gpu::Image>(ctx_, w, h, VK_FORMAT_R8G8B8A8_UNORM, "display");
  shared::DisplayPush push{settings.exposure, settings.tonemap, settings.encodeSrgb ? 1u : 0u, 0u};
  recorder.pass("display", pipeline_)
      .read(QL_DISPLAY_BIND_ACCUM, accumulation)
      .write(QL_DISPLAY_BIND_OUTPUT, *output_)
      .push(push)
      .dispatchThreads(w, h);
}

}  // namespace qlight::ui
