// The guide of unguided frames: every guide binding filled with a minimal buffer
// and every feature off, so the path passes run without cache points.
#pragma once
#include "engine/guiding/guide_bindings.h"
#include "engine/render/guide.h"

namespace qlight::guiding {

class NullGuide final : public render::Guide {
 public:
  explicit NullGuide(const gpu::Context& ctx) : placeholders_(ctx) {}
  void bind(gpu::PassBuilder& pass) const override {
    bindGuideBuffers(pass, placeholders_.buffers());
  }
  render::GuideFeatures features() const override { return {}; }

 private:
  GuidePlaceholders placeholders_;
};

}  // namespace qlight::guiding
