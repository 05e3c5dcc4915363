#include "engine/guiding/guide_bindings.h"

#include <string>

#include "shaders/shared/guiding_types.h"

namespace qlight::guiding {

void bindGuideBuffers(gpu::PassBuilder& pass, const GuideBuffers& b) {
  pass.read(QL_BIND_GUIDING, *b.uniforms)
      .read(QL_BIND_CACHE_POINTS, *b.points)
      .read(QL_BIND_GRID_BUCKETS, *b.gridBuckets)
      .read(QL_BIND_GRID_POINTS, *b.gridPoints)
      .read(QL_BIND_Q_CDF, *b.qCdf)
      .read(QL_BIND_Q_CHILDREN, *b.qChildren)
      .write(QL_BIND_Q_SUM, *b.qSums)
      .write(QL_BIND_Q_COUNT, *b.qCounts)
      .write(QL_BIND_SPAWN, *b.spawnReports)
      .read(QL_BIND_V_CDF, *b.vCdf)
      .write(QL_BIND_V_SUM, *b.vSums)
      .write(QL_BIND_V_COUNT, *b.vCounts)
      .read(QL_BIND_POINT_UPDATES, *b.pointUpdates)
      .write(QL_BIND_NEE_COUNTS, *b.neeCounts);
}

GuidePlaceholders::GuidePlaceholders(const gpu::Context& ctx) {
  shared::GuidingUniforms off{};
  off.rows = off.cols = 1;
  off.hashSize = 1;
  uniforms_ = std::make_unique<gpu::Buffer>(ctx, sizeof(off), "guiding.off");
  uniforms_->upload(ctx, &off, sizeof(off));
  empty_ = std::make_unique<gpu::Buffer>(ctx, 64, "guiding.empty", gpu::kTexelTableUsage);
  std::vector<uint8_t> zeros(64, 0);
  empty_->upload(ctx, zeros.data(), zeros.size());
  emptyFloats_ = std::make_unique<gpu::BufferView>(ctx, *empty_, VK_FORMAT_R32_SFLOAT);
  emptyVec4s_ = std::make_unique<gpu::BufferView>(ctx, *empty_, VK_FORMAT_R32G32B32A32_SFLOAT);
  emptyUints_ = std::make_unique<gpu::BufferView>(ctx, *empty_, VK_FORMAT_R32_UINT);
  emptyUvec4s_ = std::make_unique<gpu::BufferView>(ctx, *empty_, VK_FORMAT_R32G32B32A32_UINT);
  // Written bindings get their own buffers so no two bindings of one pass alias.
  for (int i = 0; i < 6; ++i) {
    writable_.push_back(
        std::make_unique<gpu::Buffer>(ctx, 64, "guiding.unused" + std::to_string(i)));
    writable_.back()->upload(ctx, zeros.data(), zeros.size());
  }
  GuideBuffers& b = buffers_;
  b.uniforms = uniforms_.get();
  b.points = emptyVec4s_.get();
  b.gridBuckets = b.gridPoints = emptyUints_.get();
  b.qCdf = b.vCdf = emptyFloats_.get();
  b.qChildren = emptyUvec4s_.get();
  b.qSums = writable_[0].get();
  b.qCounts = writable_[1].get();
  b.spawnReports = writable_[2].get();
  b.vSums = writable_[3].get();
  b.vCounts = writable_[4].get();
  b.pointUpdates = emptyUints_.get();
  b.neeCounts = writable_[5].get();
}

}  // namespace qlight::guiding
