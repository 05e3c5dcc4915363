#include "engine/ecs/registry.h"

namespace qlight::ecs {

void CommandBuffer::destroy(Entity e) {
  record([e](Registry& r) {
    if (!r.valid(e)) return false;
    r.destroy(e);
    return true;
  });
}

void Registry::destroy(Entity e) {
  requireValid(e, "destroy", "entity");
  // Check every storage first so a refused destroy leaves e whole.
  for (const auto& p : pools_) {
    if (p && p->iterationLocked() && p->contains(e)) {
      throw std::logic_error("registry.cpp: destroy: storage of " + std::string(p->typeName()) +
                             ": structural change during iteration: use deferred()");
    }
  }
  for (const auto& p : pools_) {
    if (p) p->remove(e);
  }
  entities_.destroy(e);
}

bool Registry::iterating() const {
  for (const auto& p : pools_) {
    if (p && p->iterationLocked()) return true;
  }
  return false;
}

size_t Registry::flush() {
  if (iterating()) {
    throw std::logic_error("registry.cpp: flush during iteration: flush after each() returns");
  }
  // Take the commands first: applying them must not see (or re-run) this list.
  auto commands = std::move(deferred_.commands_);
  deferred_.commands_.clear();
  size_t applied = 0;
  for (auto& command : commands) applied += command->apply(*this) ? 1 : 0;
  return applied;
}

void Registry::throwMissing(std::string_view op, std::string_view type, Entity e) const {
  const std::string handle =
      "entity (" + std::to_string(e.index) + ", gen " + std::to_string(e.generation) + ")";
  if (!valid(e)) {
    throw std::logic_error("registry.h: " + std::string(op) + "<" + std::string(type) +
                           ">: " + handle + " is stale or null");
  }
  throw std::logic_error("registry.h: " + std::string(op) + "<" + std::string(type) +
                         ">: " + handle + " has no " + std::string(type));
}

}  // namespace qlight::ecs
