// GPU timestamps around each named pass; read back after the frame's fence.
#pragma once
#include <vulkan/vulkan.h>

#include <map>
#include <string>
#include <vector>

#include "engine/gpu/context.h"

namespace qlight::gpu {

class GpuTimer {
 public:
  GpuTimer() = default;
  GpuTimer(const Context& ctx, uint32_t maxPasses = 512);
  bool enabled() const { return bool(pool_); }

  void reset(VkCommandBuffer cmd);  // start of a frame's command buffer
  void begin(VkCommandBuffer cmd, const std::string& name);
  void end(VkCommandBuffer cmd);

  // Milliseconds per pass name (passes recorded several times are summed),
  // for the frame recorded since reset(). Call after the GPU finished it.
  std::map<std::string, double> collect(const Context& ctx);

 private:
  static constexpr uint32_t kQueriesPerPass = 4;  // begin and end, each with its follower
  void stamp(VkCommandBuffer cmd);

  Unique<VkQueryPool> pool_;
  uint32_t capacity_ = 0;
  uint32_t used_ = 0;
  double periodNs_ = 0;
  std::vector<std::string> names_;
};

}  // namespace qlight::gpu
