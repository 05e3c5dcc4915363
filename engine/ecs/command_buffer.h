// Structural changes recorded while views iterate, applied by Registry::flush() in recorded
// order. Commands whose entity is no longer valid at flush time (destroyed by an earlier
// command or elsewhere) are dropped, so two systems may both ask to destroy the same entity.
// To create during iteration, call registry.create() directly (it touches no storage) and
// record the new entity's components here.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "engine/ecs/entity.h"

namespace qlight::ecs {

class Registry;

class CommandBuffer {
 public:
  void destroy(Entity e);
  // Builds the T now (from args, like Registry::emplace) and adds or replaces it at flush.
  template <class T, class... A>
  void emplace(Entity e, A&&... args);  // defined in registry.h: needs Registry complete
  template <class T>
  void remove(Entity e);

  size_t size() const { return commands_.size(); }
  bool empty() const { return commands_.empty(); }

 private:
  friend class Registry;

  struct Command {
    virtual ~Command() = default;
    virtual bool apply(Registry& registry) = 0;  // false: dropped (stale entity)
  };
  template <class F>
  struct FnCommand final : Command {
    explicit FnCommand(F f) : fn(std::move(f)) {}
    bool apply(Registry& registry) override { return fn(registry); }
    F fn;
  };
  template <class F>
  void record(F fn) {
    commands_.push_back(std::make_unique<FnCommand<F>>(std::move(fn)));
  }

  std::vector<std::unique_ptr<Command>> commands_;
};

}  // namespace qlight::ecs
