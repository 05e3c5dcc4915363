// Orders systems from the component types they declare to read and write:
//
//   scheduler.add("transforms").reads<LocalTransform>().writes<WorldTransform>().run(fn);
//
// Every system belongs to one of the frame's fixed phases (as flecs' builtin phases), which run
// in order: simulate, extract, upload, trace, learn, present. Within a phase, compile() puts
// every writer of T before every pure reader of T (producer before consumer), whatever the
// registration order; writers of the same T, and systems with no dependency between them, keep
// registration order. Across phases only the phase order counts (a later phase's writes are
// read by an earlier one in the next frame). A dependency cycle throws std::runtime_error
// naming the systems on it. Systems in one level() share no written type, so could run in
// parallel.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "engine/ecs/registry.h"
#include "engine/ecs/type_id.h"

namespace qlight::ecs {

// The frame's phases in run order. CPU systems simulate (animation, transforms) and extract
// what the renderer draws; upload moves changed data to the GPU; trace, learn and present
// systems record GPU passes (path tracing, the guide's learning, display).
enum class Phase : uint8_t { Simulate, Extract, Upload, Trace, Learn, Present };
inline constexpr size_t kPhaseCount = 6;
const char* phaseName(Phase phase);

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
    // The phase the system runs in (default: simulate).
    SystemBuilder& phase(Phase phase);
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
  // Runs the systems of one phase in compiled order (compiling first if needed).
  void runPhase(Registry& registry, Phase phase);

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
    Phase phase = Phase::Simulate;
  };
  void runEntry(Registry& registry, size_t entry);  // order_[entry], timed

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
