#include "engine/gpu/buffer.h"

#include <cstring>
#include <stdexcept>

#include "engine/gpu/vk_check.h"

namespace qlight::gpu {

Buffer::Buffer(const Context& ctx, VkDeviceSize bytes, const std::string& name,
               VkBufferUsageFlags extraUsage, MemoryUse use)
    : size_(bytes), name_(name) {
  if (bytes == 0) bytes = 4;  // Vulkan forbids empty buffers; keep a minimal one.
  VkDevice device = ctx.device();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = bytes;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT |
               VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | extraUsage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  QL_VK(vkCreateBuffer(device, &info, nullptr, &buffer));
  buffer_ = Unique<VkBuffer>(buffer, [device](VkBuffer b) { vkDestroyBuffer(device, b, nullptr); });
  ctx.setName(uint64_t(buffer), VK_OBJECT_TYPE_BUFFER, name);

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, buffer, &req);
  VkMemoryPropertyFlags required =
      use == MemoryUse::HostVisible
          ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
          : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  uint32_t type = 0;
  memory_ = ctx.allocate(req, required, &type);
  VkDeviceMemory memory = memory_;
  QL_VK(vkBindBufferMemory(device, buffer, memory, 0));

  VkPhysicalDeviceMemoryProperties props;
  vkGetPhysicalDeviceMemoryProperties(ctx.physicalDevice(), &props);
  VkMemoryPropertyFlags flags = props.memoryTypes[type].propertyFlags;
  const VkMemoryPropertyFlags mappable =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  if ((flags & mappable) == mappable)
    QL_VK(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mapped_));
}

void Buffer::upload(const Context& ctx, const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
  if (offset + bytes > size_)
    throw std::out_of_range("upload of " + std::to_string(bytes) +
                            " bytes past the end of buffer " + name_);
  if (bytes == 0) return;
  if (mapped_) {
    std::memcpy(static_cast<char*>(mapped_) + offset, data, bytes);
    return;
  }
  Buffer staging(ctx, bytes, name_ + ".staging", 0, MemoryUse::HostVisible);
  std::memcpy(staging.mapped(), data, bytes);
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, offset, bytes};
    vkCmdCopyBuffer(cmd, staging.handle(), buffer_, 1, &region);
  });
}

void Buffer::download(const Context& ctx, void* data, VkDeviceSize bytes,
                      VkDeviceSize offset) const {
  if (offset + bytes > size_) throw std::out_of_range("readback past the end of buffer " + name_);
  if (bytes == 0) return;
  if (mapped_) {
    std::memcpy(data, static_cast<const char*>(mapped_) + offset, bytes);
    return;
  }
  Buffer staging(ctx, bytes, name_ + ".readback", 0, MemoryUse::HostVisible);
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy region{offset, 0, bytes};
    vkCmdCopyBuffer(cmd, buffer_, staging.handle(), 1, &region);
  });
  std::memcpy(data, staging.mapped(), bytes);
}

BufferView::BufferView(const Context& ctx, const Buffer& buffer, VkFormat format)
    : buffer_(&buffer) {
  // Every format of ours is 4 bytes a channel: R32 (4 bytes a texel) or RGBA32 (16).
  const uint64_t texelBytes =
      format == VK_FORMAT_R32_UINT || format == VK_FORMAT_R32_SFLOAT || format == VK_FORMAT_R32_SINT
          ? 4
          : 16;
  ctx.requireBufferFits(buffer.name(), buffer.size(), false, buffer.size() / texelBytes);
  VkDevice device = ctx.device();
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer.handle();
  info.format = format;
  info.offset = 0;
  info.range = VK_WHOLE_SIZE;
  VkBufferView view = VK_NULL_HANDLE;
  QL_VK(vkCreateBufferView(device, &info, nullptr, &view));
  view_ = Unique<VkBufferView>(
      view, [device](VkBufferView v) { vkDestroyBufferView(device, v, nullptr); });
  ctx.setName(uint64_t(view), VK_OBJECT_TYPE_BUFFER_VIEW, buffer.name() + ".view");
}

}  // namespace qlight::gpu
