// Registry: entities, one Storage<T> per component type, views over them, deferred
// structural changes and resource singletons. EnTT-shaped: an entity is an index plus a
// generation; components are plain structs in dense per-type arrays.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/ecs/command_buffer.h"
#include "engine/ecs/entity.h"
#include "engine/ecs/entity_pool.h"
#include "engine/ecs/resources.h"
#include "engine/ecs/storage.h"
#include "engine/ecs/type_id.h"
#include "engine/ecs/view.h"

namespace qlight::ecs {

// Components are named by their plain type; `const T` only appears in view<>() and access<>().
template <class T>
concept Component = std::is_same_v<T, std::remove_cvref_t<T>>;

class Registry {
 public:
  Entity create() { return entities_.create(); }
  // Removes all of e's components, then invalidates e. Throws std::logic_error on a stale
  // handle, or (changing nothing) when a storage holding e is being iterated.
  void destroy(Entity e);
  bool valid(Entity e) const { return entities_.valid(e); }
  size_t aliveCount() const { return entities_.aliveCount(); }

  // Adds T to e or replaces e's T. Throws std::logic_error on a stale entity, or when adding
  // to a storage that a view is iterating.
  template <Component T, class... A>
  T& emplace(Entity e, A&&... args) {
    requireValid(e, "emplace", typeName<T>());
    return storage<T>().emplace(e, std::forward<A>(args)...);
  }
  // Removes e's T if it has one; returns whether it had. Throws on a stale entity.
  template <Component T>
  bool remove(Entity e) {
    requireValid(e, "remove", typeName<T>());
    SparseSet* p = pool(typeId<T>());
    return p && p->remove(e);
  }
  // Throws std::logic_error naming T when e is stale or has no T.
  template <Component T>
  T& get(Entity e) {
    if (T* value = tryGet<T>(e)) return *value;
    throwMissing("get", typeName<T>(), e);
  }
  template <Component T>
  const T& get(Entity e) const {
    if (const T* value = tryGet<T>(e)) return *value;
    throwMissing("get", typeName<T>(), e);
  }
  template <Component T>
  T* tryGet(Entity e) {
    auto* s = static_cast<Storage<T>*>(pool(typeId<T>()));
    return s ? s->tryGet(e) : nullptr;  // indexOf checks the generation: stale -> nullptr
  }
  template <Component T>
  const T* tryGet(Entity e) const {
    return const_cast<Registry*>(this)->tryGet<T>(e);
  }
  template <Component T>
  bool has(Entity e) const {
    const SparseSet* p = pool(typeId<T>());
    return p && p->contains(e);
  }
  // Modifies e's T in place through fn(T&) and marks its slot dirty for upload.
  template <Component T, class F>
  T& patch(Entity e, F&& fn) {
    auto* s = static_cast<Storage<T>*>(pool(typeId<T>()));
    if (!s || !s->contains(e)) throwMissing("patch", typeName<T>(), e);
    return s->patch(e, std::forward<F>(fn));
  }

  // The storage of T, created empty on first use.
  template <Component T>
  Storage<T>& storage() {
    const TypeId id = typeId<T>();
    if (id >= pools_.size()) pools_.resize(id + 1);
    if (!pools_[id]) pools_[id] = std::make_unique<Storage<T>>();
    return static_cast<Storage<T>&>(*pools_[id]);
  }
  // nullptr when no T was ever stored.
  template <Component T>
  const Storage<T>* findStorage() const {
    return static_cast<const Storage<T>*>(pool(typeId<T>()));
  }

  // Entities having every T; `const T` marks read-only access.
  template <class... T>
  View<T...> view() {
    return View<T...>(storage<std::remove_const_t<T>>()...);
  }

  // Record structural changes here while iterating; flush() applies them in order.
  CommandBuffer& deferred() { return deferred_; }
  // Applies the deferred commands; returns how many applied (the rest had stale entities).
  // Throws std::logic_error, applying nothing, while any view is iterating.
  size_t flush();
  // True while some view over this registry's storages is inside each().
  bool iterating() const;

  Resources& ctx() { return resources_; }
  const Resources& ctx() const { return resources_; }
  template <class T, class... A>
  T& setResource(A&&... args) {
    return resources_.set<T>(std::forward<A>(args)...);
  }
  template <class T>
  T& resource() const {
    return resources_.get<T>();
  }
  template <class T>
  T* tryResource() const {
    return resources_.tryGet<T>();
  }
  template <class T>
  bool hasResource() const {
    return resources_.has<T>();
  }

 private:
  SparseSet* pool(TypeId id) const { return id < pools_.size() ? pools_[id].get() : nullptr; }
  void requireValid(Entity e, std::string_view op, std::string_view type) const {
    if (!valid(e)) throwMissing(op, type, e);
  }
  // Says whether e was stale or only lacked the component.
  [[noreturn]] void throwMissing(std::string_view op, std::string_view type, Entity e) const;

  EntityPool entities_;
  std::vector<std::unique_ptr<SparseSet>> pools_;  // indexed by typeId
  CommandBuffer deferred_;
  Resources resources_;
};

// CommandBuffer's templates need a complete Registry.
template <class T, class... A>
void CommandBuffer::emplace(Entity e, A&&... args) {
  record([e, v = T(std::forward<A>(args)...)](Registry& r) mutable {
    if (!r.valid(e)) return false;
    r.emplace<T>(e, std::move(v));
    return true;
  });
}

template <class T>
void CommandBuffer::remove(Entity e) {
  record([e](Registry& r) {
    if (!r.valid(e)) return false;
    r.remove<T>(e);
    return true;
  });
}

}  // namespace qlight::ecs
