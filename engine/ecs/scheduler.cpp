#include "engine/ecs/scheduler.h"

#include <algorithm>
#include <chrono>
#include <queue>
#include <stdexcept>

namespace qlight::ecs {

const char* phaseName(Phase phase) {
  static const char* const names[kPhaseCount] = {"simulate", "extract", "upload",
                                                 "trace",    "learn",   "present"};
  return names[size_t(phase)];
}

Scheduler::SystemBuilder& Scheduler::SystemBuilder::phase(Phase phase) {
  scheduler_->systems_[index_].phase = phase;
  scheduler_->compiled_ = false;
  return *this;
}

Scheduler::SystemBuilder& Scheduler::SystemBuilder::run(SystemFn fn) {
  scheduler_->systems_[index_].fn = std::move(fn);
  return *this;
}

Scheduler::SystemBuilder Scheduler::add(std::string name) {
  if (name.empty()) throw std::runtime_error("scheduler.cpp: a system needs a name");
  for (const System& s : systems_) {
    if (s.name == name) throw std::runtime_error("scheduler.cpp: duplicate system " + name);
  }
  systems_.push_back(System{std::move(name), {}, {}});
  compiled_ = false;
  return SystemBuilder(this, systems_.size() - 1);
}

void Scheduler::declare(size_t system, TypeId type, std::string_view name, bool write) {
  auto& accesses = systems_[system].accesses;
  auto it = std::find_if(accesses.begin(), accesses.end(),
                         [&](const Access& a) { return a.type == type; });
  if (it == accesses.end()) {
    accesses.push_back(Access{type, std::string(name), write});
  } else {
    it->write = it->write || write;  // read + write of one type is a write
  }
  compiled_ = false;
}

bool Scheduler::writes(const System& s, TypeId type) const {
  return std::any_of(s.accesses.begin(), s.accesses.end(),
                     [&](const Access& a) { return a.type == type && a.write; });
}

bool Scheduler::reads(const System& s, TypeId type) const {
  return std::any_of(s.accesses.begin(), s.accesses.end(),
                     [&](const Access& a) { return a.type == type && !a.write; });
}

const std::string* Scheduler::dependency(size_t from, size_t to) const {
  if (systems_[from].phase != systems_[to].phase) return nullptr;  // phases order those
  for (const Access& a : systems_[from].accesses) {
    if (!a.write) continue;
    if (reads(systems_[to], a.type)) return &a.typeName;                // producer before consumer
    if (from < to && writes(systems_[to], a.type)) return &a.typeName;  // writers in order
  }
  return nullptr;
}

void Scheduler::compile() {
  const size_t n = systems_.size();
  for (const System& s : systems_) {
    if (!s.fn) throw std::runtime_error("scheduler.cpp: system " + s.name + " has no run()");
  }
  std::vector<std::vector<size_t>> preds(n), succs(n);
  for (size_t u = 0; u < n; ++u) {
    for (size_t v = 0; v < n; ++v) {
      if (u != v && dependency(u, v)) {
        preds[v].push_back(u);
        succs[u].push_back(v);
      }
    }
  }
  // Kahn's algorithm, always taking the ready system of the earliest phase, then the
  // earliest registered: a stable order. Dependencies stay within a phase, so a phase's
  // systems are all placed before any of the next phase's.
  using Key = std::pair<Phase, size_t>;
  std::vector<size_t> waiting(n);
  std::priority_queue<Key, std::vector<Key>, std::greater<>> ready;
  for (size_t v = 0; v < n; ++v) {
    waiting[v] = preds[v].size();
    if (waiting[v] == 0) ready.push({systems_[v].phase, v});
  }
  std::vector<size_t> order, levelOf(n, 0);
  std::vector<bool> placed(n, false);
  while (!ready.empty()) {
    const size_t u = ready.top().second;
    ready.pop();
    order.push_back(u);
    placed[u] = true;
    for (size_t p : preds[u]) levelOf[u] = std::max(levelOf[u], levelOf[p] + 1);
    for (size_t v : succs[u]) {
      if (--waiting[v] == 0) ready.push({systems_[v].phase, v});
    }
  }
  if (order.size() != n) throwCycle(preds, placed);

  order_ = std::move(order);
  level_.clear();
  names_.clear();
  for (size_t u : order_) {
    level_.push_back(levelOf[u]);
    names_.push_back(systems_[u].name);
  }
  compiled_ = true;
}

void Scheduler::throwCycle(const std::vector<std::vector<size_t>>& preds,
                           const std::vector<bool>& placed) const {
  // Every unplaced system has an unplaced predecessor: walk them back until one repeats.
  size_t v = std::find(placed.begin(), placed.end(), false) - placed.begin();
  std::vector<size_t> walk;
  std::vector<bool> seen(placed.size(), false);
  while (!seen[v]) {
    seen[v] = true;
    walk.push_back(v);
    v = *std::find_if(preds[v].begin(), preds[v].end(), [&](size_t p) { return !placed[p]; });
  }
  std::vector<size_t> cycle(std::find(walk.begin(), walk.end(), v), walk.end());
  std::reverse(cycle.begin(), cycle.end());  // the walk went consumer -> producer
  std::string message = "scheduler.cpp: dependency cycle: " + systems_[cycle[0]].name;
  for (size_t i = 0; i < cycle.size(); ++i) {
    const size_t from = cycle[i], to = cycle[(i + 1) % cycle.size()];
    message += " -[" + *dependency(from, to) + "]-> " + systems_[to].name;
  }
  throw std::runtime_error(message);
}

void Scheduler::requireCompiled() const {
  if (!compiled_) throw std::logic_error("scheduler.cpp: call compile() before order()");
}

const std::vector<std::string>& Scheduler::order() const {
  requireCompiled();
  return names_;
}

std::vector<std::vector<std::string>> Scheduler::levels() const {
  requireCompiled();
  std::vector<std::vector<std::string>> result;
  for (size_t i = 0; i < order_.size(); ++i) {
    if (level_[i] >= result.size()) result.resize(level_[i] + 1);
    result[level_[i]].push_back(names_[i]);
  }
  return result;
}

void Scheduler::runEntry(Registry& registry, size_t entry) {
  const auto start = std::chrono::steady_clock::now();
  systems_[order_[entry]].fn(registry);
  if (!registry.deferred().empty()) registry.flush();
  timingsMs_[entry] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void Scheduler::runFrame(Registry& registry) {
  if (!compiled_) compile();
  timingsMs_.assign(order_.size(), 0.0);
  for (size_t i = 0; i < order_.size(); ++i) runEntry(registry, i);
}

void Scheduler::runPhase(Registry& registry, Phase phase) {
  if (!compiled_) compile();
  timingsMs_.resize(order_.size(), 0.0);
  for (size_t i = 0; i < order_.size(); ++i)
    if (systems_[order_[i]].phase == phase) runEntry(registry, i);
}

}  // namespace qlight::ecs
