// Systems record compute passes as data: a name, a pipeline, the resources each
// binding reads or writes, push constants and a dispatch size. The recorder
// derives every barrier from those declarations (read-after-write,
// write-after-read, write-after-write), pushes the descriptors, and brackets
// the pass with GPU timestamps. System code places no barriers by hand.
#pragma once
#include <vulkan/vulkan.h>

#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/image.h"

namespace qlight::gpu {

enum class Access : uint8_t { Read, Write };

// One barrier the recorder placed, kept for tests and the profiler view.
struct BarrierRecord {
  std::string pass;                    // the pass that waits
  std::vector<std::string> resources;  // what made it wait
  std::vector<std::string> hazards;    // "RAW", "WAR", "WAW" per resource
};

class PassRecorder;

class PassBuilder {
 public:
  PassBuilder& read(uint32_t binding, const Buffer& buffer);
  PassBuilder& write(uint32_t binding, const Buffer& buffer);  // read-write
  PassBuilder& read(uint32_t binding, const BufferView& view);
  PassBuilder& write(uint32_t binding, const BufferView& view);  // storage texel buffer
  PassBuilder& read(uint32_t binding, const Image& image);
  PassBuilder& write(uint32_t binding, const Image& image);  // read-write
  template <class T>
  PassBuilder& push(const T& constants) {
    static_assert(sizeof(T) <= kMaxPushConstantBytes, "push constants too large");
    push_.resize(sizeof(T));
    std::memcpy(push_.data(), &constants, sizeof(T));
    return *this;
  }
  // Workgroup counts.
  void dispatch(uint32_t groupsX, uint32_t groupsY = 1, uint32_t groupsZ = 1);
  // Thread counts, rounded up to whole workgroups of the pipeline's local size.
  void dispatchThreads(uint32_t x, uint32_t y = 1, uint32_t z = 1);
  // Workgroup counts read by the GPU from `args` (a VkDispatchIndirectCommand at `offset`).
  void dispatchIndirect(const Buffer& args, VkDeviceSize offset = 0);

 private:
  friend class PassRecorder;
  struct Use {
    uint32_t binding;
    Access access;
    const Buffer* buffer = nullptr;
    const BufferView* view = nullptr;
    const Image* image = nullptr;
  };
  PassBuilder(PassRecorder* recorder, std::string name, const ComputePipeline* pipeline)
      : recorder_(recorder), name_(std::move(name)), pipeline_(pipeline) {}
  PassRecorder* recorder_;
  std::string name_;
  const ComputePipeline* pipeline_;
  std::vector<Use> uses_;
  std::vector<uint8_t> push_;
};

class PassRecorder {
 public:
  PassRecorder(const Context& ctx, VkCommandBuffer cmd, GpuTimer* timer = nullptr);

  PassBuilder pass(std::string name, const ComputePipeline& pipeline) {
    return PassBuilder(this, std::move(name), &pipeline);
  }
  // Transfer passes, declared the same way.
  // Fills `size` bytes from `offset` (multiples of 4; the whole buffer by default).
  void fill(const std::string& name, const Buffer& buffer, uint32_t value, VkDeviceSize offset = 0,
            VkDeviceSize size = VK_WHOLE_SIZE);
  void copy(const std::string& name, const Buffer& src, const Buffer& dst, VkDeviceSize bytes);
  void clear(const std::string& name, const Image& image);
  // Makes every write so far visible to the host and to later submissions.
  void finish();

  const std::vector<BarrierRecord>& barriers() const { return barriers_; }
  // Tests switch this off to show that the validation layer then reports a hazard.
  void setAutomaticBarriers(bool on) { automaticBarriers_ = on; }
  VkCommandBuffer commandBuffer() const { return cmd_; }

 private:
  friend class PassBuilder;
  struct ResourceUse {
    uint64_t key;
    const std::string* name;
    Access access;
    VkPipelineStageFlags2 stage;
    VkAccessFlags2 accessMask;
  };
  struct ResourceState {
    VkPipelineStageFlags2 writeStage = 0;  // unsynchronized write, if any
    VkAccessFlags2 writeAccess = 0;
    VkPipelineStageFlags2 readStages = 0;  // reads since the last write
  };
  void synchronize(const std::string& pass, const std::vector<ResourceUse>& uses);
  void recordDispatch(PassBuilder& builder, const Buffer* indirect, VkDeviceSize offset, uint32_t x,
                      uint32_t y, uint32_t z);
  void bindDescriptors(const PassBuilder& builder);

  const Context& ctx_;
  VkCommandBuffer cmd_;
  GpuTimer* timer_;
  bool automaticBarriers_ = true;
  std::unordered_map<uint64_t, ResourceState> states_;
  std::vector<BarrierRecord> barriers_;
};

}  // namespace qlight::gpu
