// Registry-wide singletons (the scene's mesh table, the frame's settings, ...): one value per
// type, owned by the registry, for data that is not per entity.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/ecs/type_id.h"

namespace qlight::ecs {

class Resources {
 public:
  // Creates or replaces the T singleton.
  template <class T, class... A>
  T& set(A&&... args) {
    auto value = std::make_shared<T>(std::forward<A>(args)...);
    T& ref = *value;
    slot<T>() = std::move(value);
    return ref;
  }
  template <class T>
  T* tryGet() const {
    const TypeId id = typeId<T>();
    return id < slots_.size() ? static_cast<T*>(slots_[id].get()) : nullptr;
  }
  // Throws std::logic_error when no T was set.
  template <class T>
  T& get() const {
    if (T* value = tryGet<T>()) return *value;
    throw std::logic_error("resources.h: no resource of type " + std::string(typeName<T>()));
  }
  template <class T>
  bool has() const {
    return tryGet<T>() != nullptr;
  }
  template <class T>
  bool erase() {
    if (!has<T>()) return false;
    slot<T>().reset();
    return true;
  }

 private:
  template <class T>
  std::shared_ptr<void>& slot() {
    const TypeId id = typeId<T>();
    if (id >= slots_.size()) slots_.resize(id + 1);
    return slots_[id];
  }
  std::vector<std::shared_ptr<void>> slots_;  // indexed by typeId; shared_ptr erases the type
};

}  // namespace qlight::ecs
