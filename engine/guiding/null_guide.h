// The guide of unguided frames: every guide binding filled with a minimal buffer
// and every feature off, so the path passes run without cache points.
#pragma once
#include <memory>
#include <vector>

#include "engine/render/guide.h"

namespace qlight::guiding {

class NullGuide final : public render::Guide {
 public:
  explicit NullGuide(const gpu::Context& ctx);
  void bind(gpu::PassBuilder& pass) const override;
  render::GuideFeatures features() const override { return {}; }

 private:
  std::unique_ptr<gpu::Buffer> uniforms_, empty_;
  std::unique_ptr<gpu::BufferView> emptyFloats_, emptyVec4s_, emptyUints_, emptyUvec4s_;
  std::vector<std::unique_ptr<gpu::Buffer>> writable_;
};

}  // namespace qlight::guiding
