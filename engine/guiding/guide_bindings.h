// The buffers every guide binds in the path tracing passes, one per binding of
// the guide block (shaders/shared/bindings.h): the one place in C++ that knows
// those slots, for the Q guide and the null guide alike.
#pragma once
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
};

void bindGuideBuffers(gpu::PassBuilder& pass, const GuideBuffers& b);

}  // namespace qlight::guiding
