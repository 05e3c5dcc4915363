// The type-erased half of a component storage: which entities it holds and where, plus the
// bookkeeping a GPU uploader and a running view need. Storage<T> adds the values.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "engine/ecs/dirty_range.h"
#include "engine/ecs/entity.h"
#include "engine/ecs/sparse_index.h"

namespace qlight::ecs {

class SparseSet {
 public:
  static constexpr uint32_t kAbsent = SparseIndex::kAbsent;

  explicit SparseSet(std::string_view typeName) : typeName_(typeName) {}
  virtual ~SparseSet() = default;
  SparseSet(const SparseSet&) = delete;
  SparseSet& operator=(const SparseSet&) = delete;

  // Removes e's component if it has one (swap-and-pop); returns whether it had one.
  virtual bool remove(Entity e) = 0;

  size_t size() const { return entities_.size(); }
  bool empty() const { return entities_.empty(); }
  // entities()[i] owns the component at dense position i.
  const std::vector<Entity>& entities() const { return entities_; }
  // Dense position of e's component, or kAbsent (also for a stale handle to a recycled slot).
  uint32_t indexOf(Entity e) const {
    const uint32_t pos = sparse_.find(e.index);
    return pos != kAbsent && entities_[pos].generation == e.generation ? pos : kAbsent;
  }
  bool contains(Entity e) const { return indexOf(e) != kAbsent; }

  // Dense positions written since clearDirty(): by emplace, markDirty, patch, a view with
  // write access, and the slot a swap-and-pop removal moved into.
  DirtyRange dirtyRange() const { return dirty_; }
  void clearDirty() { dirty_ = {}; }
  void markDirty(Entity e) {
    const uint32_t pos = indexOf(e);
    if (pos == kAbsent) throw std::logic_error(missingMessage("markDirty"));
    dirty_.include(pos);
  }
  void markDirtyRange(DirtyRange r) { dirty_.include(r); }
  void markAllDirty() {
    if (!empty()) dirty_ = {0, size()};
  }
  // Bumped whenever an entity is added or removed: the count or order of the dense arrays
  // changed, so an uploader must resize or re-upload rather than patch the dirty range.
  uint64_t structureVersion() const { return structureVersion_; }

  std::string_view typeName() const { return typeName_; }

  // Views lock the storages they iterate; adding or removing entities then throws.
  void lockIteration() { ++iterationLocks_; }
  void unlockIteration() { --iterationLocks_; }
  bool iterationLocked() const { return iterationLocks_ > 0; }

 protected:
  void throwIfIterating() const {
    if (iterationLocked()) {
      throw std::logic_error("storage of " + std::string(typeName_) +
                             ": structural change during iteration: use deferred()");
    }
  }
  std::string missingMessage(std::string_view op) const {
    return "storage.h: " + std::string(op) + ": entity has no " + std::string(typeName_);
  }
  // Appends e at the end of the dense arrays (the caller appended its value already).
  void pushEntity(Entity e) {
    if (sparse_.find(e.index) != kAbsent) {
      throw std::logic_error("storage of " + std::string(typeName_) +
                             ": a stale handle's slot holds another entity's component");
    }
    entities_.push_back(e);
    sparse_.set(e.index, uint32_t(entities_.size() - 1));
    dirty_.include(entities_.size() - 1);
    ++structureVersion_;
  }
  // Moves the last entity into pos and pops; the caller did the same to its values.
  void swapAndPopEntity(uint32_t pos) {
    const uint32_t last = uint32_t(entities_.size() - 1);
    sparse_.erase(entities_[pos].index);
    if (pos != last) {
      entities_[pos] = entities_[last];
      sparse_.set(entities_[pos].index, pos);
      dirty_.include(pos);
    }
    entities_.pop_back();
    dirty_.clampTo(entities_.size());
    ++structureVersion_;
  }

  DirtyRange dirty_;

 private:
  std::vector<Entity> entities_;
  SparseIndex sparse_;
  uint64_t structureVersion_ = 0;
  int iterationLocks_ = 0;
  std::string_view typeName_;
};

}  // namespace qlight::ecs
