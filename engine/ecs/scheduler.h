// Orders systems from the component types they declare to read and write:
//
//   scheduler.add("transforms").reads<LocalTransform>().writes<WorldTransform>().run(fn);
//
// compile() puts every writer of T before every pure reader of T (producer before consumer),
// whatever the registration order; writers of the same T, and systems with no dependency
// between them, keep registration order. A dependency cycle throws std::runtime_error naming
// the systems on it. Systems in one level() share no written type, so could run in parallel.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "engine/ecs/registry.h"
#include "engine/ecs/type_id.h"

namespace qlight::ecs {

class Scheduler {
 public:
  using SystemFn = std::function<void(Registry&)>;

  // Fluent declaration of one system; returned by add().
  class SystemBuilder {
   public:
    template <class... T>
    SystemBuilder& reads() {
      (scheduler_->declare(index_, typeId<T>(), typeName<T>(), false), ...);
      return *this;
    }
    template <class... T>
    SystemBuilder& writes() {
      (scheduler_->declare(index_, typeId<T>(), typeName<T>(), true), ...);
      return *this;
    }
    // Same spelling as view<const A, B>(): const T is read, plain T is written.
    template <class... T>
    SystemBuilder& access() {
      (scheduler_->declare(index_, typeId<T>(), typeName<T>(), !std::is_const_v<T>), ...);
      return *this;
    }
    SystemBuilder& run(SystemFn fn);

   private:
    friend class Scheduler;
    SystemBuilder(Scheduler* scheduler, size_t index) : scheduler_(scheduler), index_(index) {}
    Scheduler* scheduler_;
    size_t index_;
  };

  // Throws std::runtime_error on a duplicate or empty name.
  SystemBuilder add(std::string name);

  // Orders the systems. Throws std::runtime_error on a cycle or a system without run().
  void compile();
  // Runs every system once in compiled order (compiling first if needed), flushing the
  // registry's deferred commands after each system so the next one sees its changes.
  void runFrame(Registry& registry);

  // System names in run order; levels() groups them by dependency depth. Compile first.
  const std::vector<std::string>& order() const;
  std::vector<std::vector<std::string>> levels() const;
  // Wall time of each system in the last runFrame, in order(), milliseconds.
  const std::vector<double>& lastTimingsMs() const { return timingsMs_; }
  size_t systemCount() const { return systems_.size(); }

 private:
  struct Access {
    TypeId type;
    std::string typeName;
    bool write;
  };
  struct System {
    std::string name;
    std::vector<Access> accesses;
    SystemFn fn;
  };

  void declare(size_t system, TypeId type, std::string_view name, bool write);
  bool writes(const System& s, TypeId type) const;
  bool reads(const System& s, TypeId type) const;  // and does not write it
  // The type forcing `from` before `to`, or nullptr when they are independent.
  const std::string* dependency(size_t from, size_t to) const;
  [[noreturn]] void throwCycle(const std::vector<std::vector<size_t>>& preds,
                               const std::vector<bool>& placed) const;
  void requireCompiled() const;

  std::vector<System> systems_;
  std::vector<size_t> order_;       // indices into systems_
  std::vector<size_t> level_;       // per entry of order_
  std::vector<std::string> names_;  // names in order_
  std::vector<double> timingsMs_;
  bool compiled_ = false;
};

}  // namespace qlight::ecs
