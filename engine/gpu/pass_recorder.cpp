#include "engine/gpu/pass_recorder.h"

#include <stdexcept>

#include "engine/gpu/barrier.h"

namespace qlight::gpu {
namespace {

constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
// Fill, copy and clear all count as transfer work (the layer files vkCmdFillBuffer under COPY).
constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;

bool compatible(VkDescriptorType type, bool isBuffer, bool isView, bool isImage) {
  switch (type) {
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER:
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER:
      return isBuffer;
    case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER:
    case VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER:
      return isView;
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE:
      return isImage;
    default:
      return false;
  }
}

}  // namespace

PassBuilder& PassBuilder::read(uint32_t binding, const Buffer& buffer) {
  uses_.push_back({binding, Access::Read, &buffer});
  return *this;
}
PassBuilder& PassBuilder::write(uint32_t binding, const Buffer& buffer) {
  uses_.push_back({binding, Access::Write, &buffer});
  return *this;
}
PassBuilder& PassBuilder::read(uint32_t binding, const BufferView& view) {
  uses_.push_back({binding, Access::Read, nullptr, &view});
  return *this;
}
PassBuilder& PassBuilder::write(uint32_t binding, const BufferView& view) {
  uses_.push_back({binding, Access::Write, nullptr, &view});
  return *this;
}
PassBuilder& PassBuilder::read(uint32_t binding, const Image& image) {
  uses_.push_back({binding, Access::Read, nullptr, nullptr, &image});
  return *this;
}
PassBuilder& PassBuilder::write(uint32_t binding, const Image& image) {
  uses_.push_back({binding, Access::Write, nullptr, nullptr, &image});
  return *this;
}

void PassBuilder::dispatch(uint32_t x, uint32_t y, uint32_t z) {
  recorder_->recordDispatch(*this, nullptr, 0, x, y, z);
}

void PassBuilder::dispatchThreads(uint32_t x, uint32_t y, uint32_t z) {
  auto groups = [](uint32_t n, uint32_t size) { return (n + size - 1) / size; };
  dispatch(groups(x, pipeline_->localSize(0)), groups(y, pipeline_->localSize(1)),
           groups(z, pipeline_->localSize(2)));
}

void PassBuilder::dispatchIndirect(const Buffer& args, VkDeviceSize offset) {
  recorder_->recordDispatch(*this, &args, offset, 0, 0, 0);
}

PassRecorder::PassRecorder(const Context& ctx, VkCommandBuffer cmd, GpuTimer* timer)
    : ctx_(ctx), cmd_(cmd), timer_(timer) {}

void PassRecorder::synchronize(const std::string& pass, const std::vector<ResourceUse>& uses) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  BarrierRecord record{pass, {}, {}};
  for (const ResourceUse& use : uses) {
    ResourceState& s = states_[use.key];
    const char* hazard = nullptr;
    if (s.writeStage) {  // an earlier write not yet made visible: RAW or WAW
      barrier.srcStageMask |= s.writeStage;
      barrier.srcAccessMask |= s.writeAccess;
      hazard = use.access == Access::Read ? "RAW" : "WAW";
    } else if (use.access == Access::Write && s.readStages) {  // WAR: wait for the readers
      barrier.srcStageMask |= s.readStages;
      hazard = "WAR";
    }
    if (hazard) {
      record.resources.push_back(*use.name);
      record.hazards.push_back(hazard);
    }
  }
  if (barrier.srcStageMask && automaticBarriers_) {
    // The destination covers every stage a pass can use, so after this barrier
    // all covered earlier work is settled for any later pass.
    barrier.dstStageMask = kCompute | kTransfer | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT;
    barrier.dstAccessMask = VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT |
                            VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT |
                            VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd_, &dep);
    barriers_.push_back(record);
    // A global barrier also settles every other resource whose pending work it covers.
    for (auto& [key, s] : states_) {
      if (s.writeStage && (s.writeStage & ~barrier.srcStageMask) == 0)
        s.writeStage = 0, s.writeAccess = 0;
      if ((s.readStages & ~barrier.srcStageMask) == 0) s.readStages = 0;
    }
  }
  for (const ResourceUse& use : uses) {
    ResourceState& s = states_[use.key];
    if (use.access == Access::Write) {
      s.writeStage = use.stage;
      s.writeAccess =
          use.accessMask & (VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
      s.readStages = 0;
    } else {
      s.readStages |= use.stage;
    }
  }
}

void PassRecorder::bindDescriptors(const PassBuilder& b) {
  const ReflectedShader& shader = b.pipeline_->reflection();
  std::vector<VkWriteDescriptorSet> writes;
  std::vector<VkDescriptorBufferInfo> bufferInfos;
  std::vector<VkDescriptorImageInfo> imageInfos;
  std::vector<VkBufferView> views;
  bufferInfos.reserve(b.uses_.size());
  imageInfos.reserve(b.uses_.size());
  views.reserve(b.uses_.size());
  for (const ReflectedBinding& rb : shader.bindings) {
    const PassBuilder::Use* use = nullptr;
    for (auto& u : b.uses_)
      if (u.binding == rb.binding) use = &u;
    if (!use)
      throw std::logic_error("pass " + b.name_ + ": shader binding " + std::to_string(rb.binding) +
                             " (" + rb.name + ", " + descriptorTypeName(rb.type) +
                             ") is not bound");
    if (!compatible(rb.type, use->buffer, use->view, use->image))
      throw std::logic_error("pass " + b.name_ + ": binding " + std::to_string(rb.binding) + " (" +
                             rb.name + ") is a " + descriptorTypeName(rb.type) +
                             " in the shader but bound to another kind of resource");
    if (use->access == Access::Write && rb.readOnly)
      throw std::logic_error("pass " + b.name_ + ": binding " + std::to_string(rb.binding) + " (" +
                             rb.name + ") is declared written but is readonly in the shader");
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = rb.binding;
    w.descriptorCount = 1;
    w.descriptorType = rb.type;
    if (use->buffer) {
      bufferInfos.push_back({use->buffer->handle(), 0, VK_WHOLE_SIZE});
      w.pBufferInfo = &bufferInfos.back();
    } else if (use->view) {
      views.push_back(use->view->handle());
      w.pTexelBufferView = &views.back();
    } else {
      imageInfos.push_back({VK_NULL_HANDLE, use->image->view(), VK_IMAGE_LAYOUT_GENERAL});
      w.pImageInfo = &imageInfos.back();
    }
    writes.push_back(w);
  }
  for (auto& u : b.uses_) {
    bool found = false;
    for (auto& rb : shader.bindings) found |= rb.binding == u.binding;
    if (!found)
      throw std::logic_error("pass " + b.name_ + " binds binding " + std::to_string(u.binding) +
                             " but shader " + b.pipeline_->name() + " declares no such binding");
  }
  if (!writes.empty())
    ctx_.cmdPushDescriptorSet(cmd_, VK_PIPELINE_BIND_POINT_COMPUTE, b.pipeline_->layout(), 0,
                              uint32_t(writes.size()), writes.data());
}

void PassRecorder::recordDispatch(PassBuilder& b, const Buffer* indirect, VkDeviceSize offset,
                                  uint32_t x, uint32_t y, uint32_t z) {
  if (b.pipeline_->reflection().hasPushConstants && b.push_.empty())
    throw std::logic_error("pass " + b.name_ + ": shader has push constants but none were given");
  std::vector<ResourceUse> uses;
  for (auto& u : b.uses_) {
    const void* handle = u.buffer ? (const void*)u.buffer->handle()
                         : u.view ? (const void*)u.view->buffer()->handle()
                                  : (const void*)u.image->handle();
    const std::string* name = u.buffer ? &u.buffer->name()
                              : u.view ? &u.view->buffer()->name()
                                       : &u.image->name();
    VkAccessFlags2 mask = u.access == Access::Read
                              ? VK_ACCESS_2_SHADER_READ_BIT
                              : VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT;
    uses.push_back({uint64_t(handle), name, u.access, kCompute, mask});
  }
  if (indirect)
    uses.push_back({uint64_t((const void*)indirect->handle()), &indirect->name(), Access::Read,
                    VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT});
  synchronize(b.name_, uses);

  if (timer_) timer_->begin(cmd_, b.name_);
  vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_COMPUTE, b.pipeline_->handle());
  bindDescriptors(b);
  if (!b.push_.empty())
    vkCmdPushConstants(cmd_, b.pipeline_->layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                       uint32_t(b.push_.size()), b.push_.data());
  if (indirect)
    vkCmdDispatchIndirect(cmd_, indirect->handle(), offset);
  else if (x && y && z)
    vkCmdDispatch(cmd_, x, y, z);
  if (timer_) timer_->end(cmd_);
}

void PassRecorder::fill(const std::string& name, const Buffer& buffer, uint32_t value,
                        VkDeviceSize offset, VkDeviceSize size) {
  synchronize(name, {{uint64_t((const void*)buffer.handle()), &buffer.name(), Access::Write,
                      kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT}});
  if (timer_) timer_->begin(cmd_, name);
  vkCmdFillBuffer(cmd_, buffer.handle(), offset, size, value);
  if (timer_) timer_->end(cmd_);
}

void PassRecorder::copy(const std::string& name, const Buffer& src, const Buffer& dst,
                        VkDeviceSize bytes) {
  synchronize(name, {{uint64_t((const void*)src.handle()), &src.name(), Access::Read, kTransfer,
                      VK_ACCESS_2_TRANSFER_READ_BIT},
                     {uint64_t((const void*)dst.handle()), &dst.name(), Access::Write, kTransfer,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT}});
  if (timer_) timer_->begin(cmd_, name);
  VkBufferCopy region{0, 0, bytes};
  vkCmdCopyBuffer(cmd_, src.handle(), dst.handle(), 1, &region);
  if (timer_) timer_->end(cmd_);
}

void PassRecorder::clear(const std::string& name, const Image& image) {
  synchronize(name, {{uint64_t((const void*)image.handle()), &image.name(), Access::Write,
                      kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT}});
  if (timer_) timer_->begin(cmd_, name);
  VkClearColorValue zero{};
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd_, image.handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
  if (timer_) timer_->end(cmd_);
}

void PassRecorder::finish() {
  memoryBarrier(
      cmd_, kCompute | kTransfer, VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
      VK_PIPELINE_STAGE_2_HOST_BIT | VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
      VK_ACCESS_2_HOST_READ_BIT | VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
  states_.clear();
}

}  // namespace qlight::gpu
