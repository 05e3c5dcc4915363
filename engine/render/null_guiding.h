// Minimal guiding buffers (no cache points, everything off) for frames rendered
// without Q-learned guiding: the path tracing passes bind the guiding slots always.
#pragma once
#include <functional>
#include <memory>

#include "engine/gpu/pass_recorder.h"

namespace qlight::render {

// Binds QL_BIND_GUIDING .. QL_BIND_V_COUNT of a path tracing pass, and says
// which guiding features the frame uses (the passes are specialized on them:
// on lavapipe both sides of every branch run, so unused code must not exist).
struct GuidingBinder {
  std::function<void(gpu::PassBuilder&)> bind;
  bool points = false;         // cache points are searched (guided sampling or learning)
  bool lightLearning = false;  // learned light selection
  explicit operator bool() const { return bool(bind); }
};

class NullGuiding {
 public:
  explicit NullGuiding(const gpu::Context& ctx);
  void bind(gpu::PassBuilder& pass) const;

 private:
  std::unique_ptr<gpu::Buffer> uniforms_, empty_;
  std::unique_ptr<gpu::BufferView> emptyFloats_, emptyVec4s_, emptyUints_;
  std::vector<std::unique_ptr<gpu::Buffer>> writable_;
};

}  // namespace qlight::render
