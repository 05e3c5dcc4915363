// Storage<T>: one component type as a sparse set. Values live in a dense std::vector<T> in
// the same order as entities(), with no holes, so data() can be copied to a GPU buffer as is.
#pragma once

#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/ecs/sparse_set.h"
#include "engine/ecs/type_id.h"

namespace qlight::ecs {

template <class T>
class Storage final : public SparseSet {
 public:
  using value_type = T;

  Storage() : SparseSet(ecs::typeName<T>()) {}

  // Adds e's component, or replaces it in place when e has one (not a structural change).
  template <class... A>
  T& emplace(Entity e, A&&... args) {
    const uint32_t pos = indexOf(e);
    if (pos != kAbsent) {
      values_[pos] = T(std::forward<A>(args)...);
      dirty_.include(pos);
      return values_[pos];
    }
    throwIfIterating();
    values_.emplace_back(std::forward<A>(args)...);
    try {
      pushEntity(e);
    } catch (...) {
      values_.pop_back();
      throw;
    }
    return values_.back();
  }

  bool remove(Entity e) override {
    const uint32_t pos = indexOf(e);
    if (pos == kAbsent) return false;
    throwIfIterating();
    if (pos + 1 != values_.size()) values_[pos] = std::move(values_.back());
    values_.pop_back();
    swapAndPopEntity(pos);
    return true;
  }

  T& get(Entity e) { return values_[checkedIndex(e)]; }
  const T& get(Entity e) const { return values_[checkedIndex(e)]; }
  T* tryGet(Entity e) {
    const uint32_t pos = indexOf(e);
    return pos == kAbsent ? nullptr : &values_[pos];
  }
  const T* tryGet(Entity e) const { return const_cast<Storage*>(this)->tryGet(e); }

  // Modifies e's component in place and marks its slot dirty.
  template <class F>
  T& patch(Entity e, F&& fn) {
    const uint32_t pos = checkedIndex(e);
    std::forward<F>(fn)(values_[pos]);
    dirty_.include(pos);
    return values_[pos];
  }

  // Raw dense access. Writes through data() are not tracked: call markDirty for them.
  T* data() { return values_.data(); }
  const T* data() const { return values_.data(); }
  const std::vector<T>& values() const { return values_; }
  T& at(size_t pos) { return values_[pos]; }
  const T& at(size_t pos) const { return values_[pos]; }

 private:
  uint32_t checkedIndex(Entity e) const {
    const uint32_t pos = indexOf(e);
    if (pos == kAbsent) throw std::logic_error(missingMessage("get"));
    return pos;
  }

  std::vector<T> values_;
};

}  // namespace qlight::ecs
