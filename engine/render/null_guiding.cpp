#include "engine/render/null_guiding.h"

#include "shaders/shared/guiding_types.h"

namespace qlight::render {

NullGuiding::NullGuiding(const gpu::Context& ctx) {
  shared::GuidingUniforms off{};
  off.rows = off.cols = 1;
  off.hashSize = 1;
  uniforms_ = std::make_unique<gpu::Buffer>(ctx, sizeof(off), "guiding.off");
  uniforms_->upload(ctx, &off, sizeof(off));
  empty_ = std::make_unique<gpu::Buffer>(ctx, 64, "guiding.empty",
                                         VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
  std::vector<uint8_t> zeros(64, 0);
  empty_->upload(ctx, zeros.data(), zeros.size());
  emptyFloats_ = std::make_unique<gpu::BufferView>(ctx, *empty_, VK_FORMAT_R32_SFLOAT);
  emptyVec4s_ = std::make_unique<gpu::BufferView>(ctx, *empty_, VK_FORMAT_R32G32B32A32_SFLOAT);
  emptyUints_ = std::make_unique<gpu::BufferView>(ctx, *empty_, VK_FORMAT_R32_UINT);
  // Written slots get their own buffers so no two bindings of one pass alias.
  for (int i = 0; i < 5; ++i) {
    writable_.push_back(std::make_unique<gpu::Buffer>(ctx, 64, "guiding.unused" + std::to_string(i)));
    writable_.back()->upload(ctx, zeros.data(), zeros.size());
  }
}

void NullGuiding::bind(gpu::PassBuilder& pass) const {
  pass.read(QL_BIND_GUIDING, *uniforms_)
      .read(QL_BIND_CACHE_POINTS, *emptyVec4s_)
      .read(QL_BIND_GRID_BUCKETS, *emptyUints_)
      .read(QL_BIND_GRID_POINTS, *emptyUints_)
      .read(QL_BIND_Q_CDF, *emptyFloats_)
      .read(QL_BIND_V_CDF, *emptyFloats_)
      .write(QL_BIND_Q_SUM, *writable_[0])
      .write(QL_BIND_Q_COUNT, *writable_[1])
      .write(QL_BIND_SPAWN, *writable_[2])
      .write(QL_BIND_V_SUM, *writable_[3])
      .write(QL_BIND_V_COUNT, *writable_[4])
      .read(QL_BIND_POINT_UPDATES, *empty_);
}

}  // namespace qlight::render
