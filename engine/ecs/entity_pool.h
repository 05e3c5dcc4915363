// Allocates entity handles: recycles slot indices through a free list and bumps a slot's
// generation on destroy so stale handles are detected, never aliased.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "engine/ecs/entity.h"

namespace qlight::ecs {

class EntityPool {
 public:
  // A slot whose generation would reach maxGeneration is retired instead of recycled, so a
  // generation never wraps around to a value an old handle still holds. kNullEntity's
  // generation is above the default limit. Tests pass a small limit to reach retirement.
  static constexpr uint32_t kMaxGeneration = std::numeric_limits<uint32_t>::max() - 1;
  static constexpr uint32_t kMaxIndex = std::numeric_limits<uint32_t>::max() - 1;

  explicit EntityPool(uint32_t maxGeneration = kMaxGeneration) : maxGeneration_(maxGeneration) {}

  Entity create();
  // Throws std::logic_error on a stale or null handle.
  void destroy(Entity e);
  bool valid(Entity e) const {
    return e.index < slots_.size() && slots_[e.index].alive &&
           slots_[e.index].generation == e.generation;
  }
  size_t aliveCount() const { return alive_; }
  // Slots ever allocated (alive, free and retired); an upper bound for entity indices.
  size_t capacity() const { return slots_.size(); }
  size_t retiredCount() const { return retired_; }

 private:
  struct Slot {
    uint32_t generation;
    bool alive;
  };
  std::vector<Slot> slots_;
  std::vector<uint32_t> free_;  // LIFO: the most recently freed index is reused first
  size_t alive_ = 0;
  size_t retired_ = 0;
  uint32_t maxGeneration_;
};

}  // namespace qlight::ecs
