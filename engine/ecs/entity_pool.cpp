#include "engine/ecs/entity_pool.h"

#include <stdexcept>
#include <string>

namespace qlight::ecs {

Entity EntityPool::create() {
  uint32_t index;
  if (!free_.empty()) {
    index = free_.back();
    free_.pop_back();
  } else {
    if (slots_.size() > kMaxIndex) {
      throw std::runtime_error("entity_pool.cpp: entity index space exhausted");
    }
    index = uint32_t(slots_.size());
    slots_.push_back(Slot{0, false});
  }
  slots_[index].alive = true;
  ++alive_;
  return Entity{index, slots_[index].generation};
}

void EntityPool::destroy(Entity e) {
  if (!valid(e)) {
    throw std::logic_error("entity_pool.cpp: destroy of a stale entity (index " +
                           std::to_string(e.index) + ", generation " +
                           std::to_string(e.generation) + ")");
  }
  Slot& slot = slots_[e.index];
  slot.alive = false;
  --alive_;
  if (slot.generation + 1 >= maxGeneration_) {
    ++retired_;  // keep the slot dead forever rather than reuse a generation
    return;
  }
  ++slot.generation;
  free_.push_back(e.index);
}

}  // namespace qlight::ecs
