// View<T...>: every entity that has all of T..., visited once each by each(fn). A `const T`
// is read-only: the view hands `const T&` and, unlike a writable T, does not mark it dirty.
// Iteration walks the smallest storage densely and probes the others through their sparse
// index. While each() runs, the storages are locked: adding or removing their entities
// throws (record the change in registry.deferred() and flush() after).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "engine/ecs/storage.h"

namespace qlight::ecs {

template <class... T>
class View {
  static_assert(sizeof...(T) > 0, "view<>() needs at least one component type");
  static constexpr size_t kCount = sizeof...(T);
  using Indices = std::index_sequence_for<T...>;

  template <class U>
  using StorageOf = Storage<std::remove_const_t<U>>;
  template <class U>
  using RefOf = std::conditional_t<std::is_const_v<U>, const std::remove_const_t<U>&, U&>;

 public:
  explicit View(StorageOf<T>&... storages) : storages_{&storages...} {}

  // fn(Entity, RefOf<T>...) or fn(RefOf<T>...), in the driving storage's dense order.
  template <class F>
  void each(F&& fn) const {
    static_assert(
        std::is_invocable_v<F&, Entity, RefOf<T>...> || std::is_invocable_v<F&, RefOf<T>...>,
        "view.each: callback must take (Entity, components...) or (components...)");
    IterationLock lock(storages_);
    const size_t driver = smallestStorage();
    [&]<size_t... I>(std::index_sequence<I...>) {
      ((driver == I ? eachDrivenBy<I>(fn) : void()), ...);
    }
    (Indices{});
  }

  // Upper bound on the number of matches: the smallest storage's size.
  size_t sizeHint() const { return sizesArray()[smallestStorage()]; }

  bool contains(Entity e) const {
    return std::apply([&](auto*... s) { return (s->contains(e) && ...); }, storages_);
  }

 private:
  using Positions = std::array<uint32_t, kCount>;

  // Locks every storage of the view for the duration of an each(), even on an exception.
  class IterationLock {
   public:
    explicit IterationLock(const std::tuple<StorageOf<T>*...>& s) : s_(s) {
      std::apply([](auto*... p) { (p->lockIteration(), ...); }, s_);
    }
    ~IterationLock() {
      std::apply([](auto*... p) { (p->unlockIteration(), ...); }, s_);
    }

   private:
    const std::tuple<StorageOf<T>*...>& s_;
  };

  // Min/max dense position handed out per writable storage; marked dirty even on exceptions.
  class WriteTracker {
   public:
    explicit WriteTracker(const std::tuple<StorageOf<T>*...>& s) : s_(s) {
      lo_.fill(std::numeric_limits<uint32_t>::max());
      hi_.fill(0);
    }
    ~WriteTracker() {
      [&]<size_t... I>(std::index_sequence<I...>) { (markWritten<I>(), ...); }
      (Indices{});
    }
    void record(const Positions& pos) {
      [&]<size_t... I>(std::index_sequence<I...>) { (recordOne<I>(pos[I]), ...); }
      (Indices{});
    }

   private:
    template <size_t I>
    void recordOne(uint32_t p) {
      if constexpr (!std::is_const_v<std::tuple_element_t<I, std::tuple<T...>>>) {
        lo_[I] = std::min(lo_[I], p);
        hi_[I] = std::max(hi_[I], p);
      }
    }
    template <size_t I>
    void markWritten() {
      if (lo_[I] <= hi_[I]) std::get<I>(s_)->markDirtyRange({lo_[I], size_t(hi_[I]) + 1});
    }
    const std::tuple<StorageOf<T>*...>& s_;
    Positions lo_, hi_;
  };

  std::array<size_t, kCount> sizesArray() const {
    return std::apply([](auto*... s) { return std::array<size_t, kCount>{s->size()...}; },
                      storages_);
  }

  size_t smallestStorage() const {
    const auto n = sizesArray();
    size_t best = 0;
    for (size_t i = 1; i < kCount; ++i) best = n[i] < n[best] ? i : best;
    return best;
  }

  // Storages filled in the same order hold e at the same position: check that slot before
  // going through the sparse index.
  template <size_t I>
  uint32_t probe(Entity e, size_t i, const Entity* owners, size_t size) const {
    if (i < size && owners[i] == e) return uint32_t(i);
    return std::get<I>(storages_)->indexOf(e);
  }

  template <size_t D, class F>
  void eachDrivenBy(F& fn) const {
    const auto& driver = *std::get<D>(storages_);
    const Entity* entities = driver.entities().data();
    const size_t n = driver.size();
    // Storages are locked, so these pointers stay valid for the whole loop.
    const auto data =
        std::apply([](auto*... s) { return std::make_tuple(s->data()...); }, storages_);
    const auto owners = std::apply(
        [](auto*... s) { return std::array<const Entity*, kCount>{s->entities().data()...}; },
        storages_);
    const auto sizes = sizesArray();
    WriteTracker written(storages_);
    Positions pos{};
    for (size_t i = 0; i < n; ++i) {
      const Entity e = entities[i];
      pos[D] = uint32_t(i);
      const bool all = [&]<size_t... I>(std::index_sequence<I...>) {
        return ((I == D || (pos[I] = probe<I>(e, i, owners[I], sizes[I])) != SparseSet::kAbsent) &&
                ...);
      }
      (Indices{});
      if (!all) continue;
      written.record(pos);
      [&]<size_t... I>(std::index_sequence<I...>) {
        if constexpr (std::is_invocable_v<F&, Entity, RefOf<T>...>) {
          fn(e, static_cast<RefOf<T>>(std::get<I>(data)[pos[I]])...);
        } else {
          fn(static_cast<RefOf<T>>(std::get<I>(data)[pos[I]])...);
        }
      }
      (Indices{});
    }
  }

  std::tuple<StorageOf<T>*...> storages_;
};

}  // namespace qlight::ecs
