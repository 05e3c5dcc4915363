// GPU inclusive prefix sums over float buffers: one long scan (any length) or
// many equal segments (the per-point CDFs of the learned distributions).
#pragma once
#include <memory>
#include <vector>

#include "engine/gpu/pass_recorder.h"

namespace qlight::gpu {

class PrefixSum {
 public:
  explicit PrefixSum(const Context& ctx);

  // Inclusive scan of the first `count` floats of `data`, in place.
  void scan(PassRecorder& recorder, const Buffer& data, uint32_t count);
  // Inclusive scan restarting every `segmentLength` (<= 1024) floats, in place.
  void scanSegments(PassRecorder& recorder, const Buffer& data, uint32_t segmentCount,
                    uint32_t segmentLength);

  static constexpr uint32_t kMaxSegmentLength = 1024;

 private:
  void scanLevel(PassRecorder& recorder, const Buffer& data, uint32_t count, uint32_t level);
  const Buffer& tileSums(uint32_t level, uint32_t tiles);

  const Context& ctx_;
  ComputePipeline tilesPipeline_;
  ComputePipeline addPipeline_;
  // Scratch per recursion level; replaced buffers stay alive until destruction
  // because a recorded command buffer may still use them.
  std::vector<std::unique_ptr<Buffer>> levels_;
  std::vector<std::unique_ptr<Buffer>> retired_;
};

}  // namespace qlight::gpu
