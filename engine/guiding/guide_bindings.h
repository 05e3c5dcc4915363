// The buffers every guide binds in the path tracing passes, one per binding of
// the guide block (shaders/shared/bindings.h): the one place in C++ that knows
// those slots, for the Q guide, the deep Q guide and the null guide alike. (The deep Q
// guide binds its network to qCdf, its replay ring to qSums and the ring's count to qCounts:
// push descriptors allow 32 bindings a pass, and the path passes use all 32 without it.)
#pragma once
#include <memory>
#include <vector>

#include "engine/gpu/pass_recorder.h"

namespace qlight::guiding {

struct GuideBuffers {
  const gpu::Buffer* uniforms = nullptr;  // shared::GuidingUniforms
  const gpu::BufferView* points = nullptr;
  const gpu::BufferView* gridBuckets = nullptr;
  const gpu::BufferView* gridPoints = nullptr;
  const gpu::BufferView* qCdf = nullptr;
  const gpu::BufferView* qChildren = nullptr;  // direction trees (a placeholder with strata)
  const gpu::Buffer* qSums = nullptr;
  const gpu::Buffer* qCounts = nullptr;
  const gpu::Buffer* spawnReports = nullptr;
  const gpu::BufferView* vCdf = nullptr;
  const gpu::Buffer* vSums = nullptr;
  const gpu::Buffer* vCounts = nullptr;
  const gpu::BufferView* pointUpdates = nullptr;
  const gpu::Buffer* neeCounts = nullptr;
};

void bindGuideBuffers(gpu::PassBuilder& pass, const GuideBuffers& b);

// Minimal buffers for every guide binding, with guiding off in their uniforms: the null
// guide binds only these, the deep Q guide these for the cache points' bindings.
class GuidePlaceholders {
 public:
  explicit GuidePlaceholders(const gpu::Context& ctx);
  const GuideBuffers& buffers() const { return buffers_; }

 private:
  std::unique_ptr<gpu::Buffer> uniforms_, empty_;
  std::unique_ptr<gpu::BufferView> emptyFloats_, emptyVec4s_, emptyUints_, emptyUvec4s_;
  std::vector<std::unique_ptr<gpu::Buffer>> writable_;
  GuideBuffers buffers_;
};

}  // namespace qlight::guiding
