// One move-only owner type for every Vulkan object: the handle plus the call
// that destroys it, run exactly once when the owner goes away.
#pragma once
#include <functional>
#include <utility>

namespace qlight::gpu {

template <class Handle>
class Unique {
 public:
  Unique() = default;
  Unique(Handle handle, std::function<void(Handle)> destroy)
      : handle_(handle), destroy_(std::move(destroy)) {}
  Unique(const Unique&) = delete;
  Unique& operator=(const Unique&) = delete;
  Unique(Unique&& other) noexcept { *this = std::move(other); }
  Unique& operator=(Unique&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, Handle{});
      destroy_ = std::move(other.destroy_);
      other.destroy_ = nullptr;
    }
    return *this;
  }
  ~Unique() { reset(); }

  void reset() {
    if (handle_ != Handle{} && destroy_) destroy_(handle_);
    handle_ = Handle{};
    destroy_ = nullptr;
  }
  Handle get() const { return handle_; }
  operator Handle() const { return handle_; }
  explicit operator bool() const { return handle_ != Handle{}; }

 private:
  Handle handle_{};
  std::function<void(Handle)> destroy_;
};

}  // namespace qlight::gpu
