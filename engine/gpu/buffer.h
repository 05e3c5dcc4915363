// GPU buffers with upload and readback, and texel-buffer views over them.
#pragma once
#include <vulkan/vulkan.h>

#include <span>
#include <string>
#include <vector>

#include "engine/gpu/context.h"

namespace qlight::gpu {

enum class MemoryUse {
  DeviceLocal,  // fastest for the GPU; mapped too when the device allows it (lavapipe)
  HostVisible,  // mapped, coherent: staging, readback, per-frame constants
};

// Usage of a table the shaders read through a texel view: declared as a read-only
// imageBuffer and read with imageLoad (on lavapipe 4-11% faster traversal than texelFetch on
// a samplerBuffer, docs/performance_log.md), or as a samplerBuffer where its format varies.
constexpr VkBufferUsageFlags kTexelTableUsage =
    VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT;

class Buffer {
 public:
  Buffer() = default;
  // Usage always includes storage + transfer src/dst; `extraUsage` adds e.g. texel usage.
  Buffer(const Context& ctx, VkDeviceSize bytes, const std::string& name,
         VkBufferUsageFlags extraUsage = 0, MemoryUse use = MemoryUse::DeviceLocal);

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }
  const std::string& name() const { return name_; }
  explicit operator bool() const { return bool(buffer_); }

  void upload(const Context& ctx, const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
  void download(const Context& ctx, void* data, VkDeviceSize bytes, VkDeviceSize offset = 0) const;

  template <class T>
  void upload(const Context& ctx, std::span<const T> values, VkDeviceSize offset = 0) {
    upload(ctx, values.data(), values.size_bytes(), offset);
  }
  template <class T>
  std::vector<T> read(const Context& ctx) const {
    std::vector<T> out(size_ / sizeof(T));
    download(ctx, out.data(), out.size() * sizeof(T));
    return out;
  }

 private:
  Unique<VkBuffer> buffer_;
  Unique<VkDeviceMemory> memory_;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  std::string name_;
};

// A typed view for imageLoad on imageBuffer or texelFetch on samplerBuffer: on lavapipe
// texel loads vectorize where storage-buffer loads become per-lane loops.
class BufferView {
 public:
  BufferView() = default;
  BufferView(const Context& ctx, const Buffer& buffer, VkFormat format);
  VkBufferView handle() const { return view_; }
  const Buffer* buffer() const { return buffer_; }

 private:
  Unique<VkBufferView> view_;
  const Buffer* buffer_ = nullptr;
};

}  // namespace qlight::gpu
