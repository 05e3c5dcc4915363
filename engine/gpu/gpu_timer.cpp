#include "engine/gpu/gpu_timer.h"

#include "engine/gpu/vk_check.h"

namespace qlight::gpu {

GpuTimer::GpuTimer(const Context& ctx, uint32_t maxPasses) : periodNs_(ctx.timestampPeriodNs()) {
  if (periodNs_ <= 0) return;  // queue without timestamps: timing is off, the rest works
  capacity_ = maxPasses * kQueriesPerPass;
  VkDevice device = ctx.device();
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = capacity_;
  VkQueryPool pool = VK_NULL_HANDLE;
  QL_VK(vkCreateQueryPool(device, &info, nullptr, &pool));
  pool_ = Unique<VkQueryPool>(pool,
                              [device](VkQueryPool p) { vkDestroyQueryPool(device, p, nullptr); });
}

void GpuTimer::reset(VkCommandBuffer cmd) {
  if (!pool_) return;
  vkCmdResetQueryPool(cmd, pool_, 0, capacity_);
  used_ = 0;
  names_.clear();
}

// Each stamp is followed by a second one whose value is never read. lavapipe, once a
// render pass has run on its queue (the window's ImGui), takes a timestamp's time when the
// next timestamp command flushes, not where it stands: alone, every pass would read the
// few microseconds between its end and the next pass's begin. The follower flushes at once.
void GpuTimer::stamp(VkCommandBuffer cmd) {
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, used_++);
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, used_++);
}

void GpuTimer::begin(VkCommandBuffer cmd, const std::string& name) {
  if (!pool_ || used_ + kQueriesPerPass > capacity_) return;
  names_.push_back(name);
  stamp(cmd);
}

void GpuTimer::end(VkCommandBuffer cmd) {
  if (!pool_ || used_ % kQueriesPerPass == 0) return;
  stamp(cmd);
}

std::map<std::string, double> GpuTimer::collect(const Context& ctx) {
  std::map<std::string, double> ms;
  if (!pool_ || used_ == 0) return ms;
  std::vector<uint64_t> ticks(used_);
  QL_VK(vkGetQueryPoolResults(ctx.device(), pool_, 0, used_, ticks.size() * sizeof(uint64_t),
                              ticks.data(), sizeof(uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  for (size_t i = 0; i + kQueriesPerPass <= ticks.size(); i += kQueriesPerPass)
    ms[names_[i / kQueriesPerPass]] += double(ticks[i + 2] - ticks[i]) * periodNs_ * 1e-6;
  return ms;
}

}  // namespace qlight::gpu
