// An entity is a handle: a slot index plus the slot's generation when the handle was made.
// Destroying an entity bumps its slot's generation, so every old handle to it goes stale
// (detectably) even after the slot is recycled for a new entity.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>

namespace qlight::ecs {

struct Entity {
  uint32_t index;
  uint32_t generation;

  friend constexpr bool operator==(Entity, Entity) = default;
};

// Never a live entity: index and generation are both out of the range the pool hands out.
inline constexpr Entity kNullEntity{std::numeric_limits<uint32_t>::max(),
                                    std::numeric_limits<uint32_t>::max()};

struct EntityHash {
  size_t operator()(Entity e) const noexcept {
    const uint64_t key = (uint64_t(e.generation) << 32) | e.index;
    return std::hash<uint64_t>{}(key);
  }
};

}  // namespace qlight::ecs

template <>
struct std::hash<qlight::ecs::Entity> : qlight::ecs::EntityHash {};
