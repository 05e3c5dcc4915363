// ECS iteration cost against raw std::vector loops: 1M entities integrating positions.
// Reported as ns per entity through the "per_entity" counter (inverted rate).
#include <benchmark/benchmark.h>

#include <vector>

#include "engine/ecs/registry.h"

namespace {

using qlight::ecs::Entity;
using qlight::ecs::Registry;

struct Position {
  float x, y, z;
};
struct Velocity {
  float x, y, z;
};
struct Damping {  // on every other entity: the sparse third component
  float factor;
};

constexpr size_t kEntities = 1'000'000;
constexpr float kDt = 1.0f / 60.0f;

void reportPerEntity(benchmark::State& state, size_t entities) {
  state.counters["per_entity"] =
      benchmark::Counter(double(entities), benchmark::Counter::kIsIterationInvariantRate |
                                               benchmark::Counter::kInvert);
}

Registry& world(bool withDamping) {
  static Registry* registries[2] = {nullptr, nullptr};
  Registry*& registry = registries[withDamping];
  if (!registry) {
    registry = new Registry;
    for (size_t i = 0; i < kEntities; ++i) {
      const Entity e = registry->create();
      registry->emplace<Position>(e, 0.0f, 0.0f, 0.0f);
      registry->emplace<Velocity>(e, 1.0f, float(i % 7), -1.0f);
      if (withDamping && i % 2 == 0) registry->emplace<Damping>(e, 0.99f);
    }
  }
  return *registry;
}

void BM_View2_PositionVelocity(benchmark::State& state) {
  Registry& registry = world(false);
  auto view = registry.view<Position, const Velocity>();
  for (auto _ : state) {
    view.each([](Position& p, const Velocity& v) {
      p.x += v.x * kDt;
      p.y += v.y * kDt;
      p.z += v.z * kDt;
    });
    benchmark::ClobberMemory();
  }
  reportPerEntity(state, kEntities);
}

void BM_Raw2_PositionVelocity(benchmark::State& state) {
  std::vector<Position> positions(kEntities, Position{0.0f, 0.0f, 0.0f});
  std::vector<Velocity> velocities(kEntities);
  for (size_t i = 0; i < kEntities; ++i) velocities[i] = {1.0f, float(i % 7), -1.0f};
  for (auto _ : state) {
    for (size_t i = 0; i < kEntities; ++i) {
      positions[i].x += velocities[i].x * kDt;
      positions[i].y += velocities[i].y * kDt;
      positions[i].z += velocities[i].z * kDt;
    }
    benchmark::ClobberMemory();
  }
  reportPerEntity(state, kEntities);
}

// Driven by the smaller Damping storage (500k), probing Position and Velocity.
void BM_View3_SparseDamping(benchmark::State& state) {
  Registry& registry = world(true);
  auto view = registry.view<Position, const Velocity, const Damping>();
  for (auto _ : state) {
    view.each([](Position& p, const Velocity& v, const Damping& d) {
      p.x = (p.x + v.x * kDt) * d.factor;
      p.y = (p.y + v.y * kDt) * d.factor;
      p.z = (p.z + v.z * kDt) * d.factor;
    });
    benchmark::ClobberMemory();
  }
  reportPerEntity(state, kEntities / 2);  // per visited entity
}

// Raw baseline for the same work: an index list of the damped entities.
void BM_Raw3_SparseDamping(benchmark::State& state) {
  std::vector<Position> positions(kEntities, Position{0.0f, 0.0f, 0.0f});
  std::vector<Velocity> velocities(kEntities);
  std::vector<Damping> damping;
  std::vector<uint32_t> damped;
  for (size_t i = 0; i < kEntities; ++i) {
    velocities[i] = {1.0f, float(i % 7), -1.0f};
    if (i % 2 == 0) {
      damping.push_back({0.99f});
      damped.push_back(uint32_t(i));
    }
  }
  for (auto _ : state) {
    for (size_t k = 0; k < damped.size(); ++k) {
      const uint32_t i = damped[k];
      positions[i].x = (positions[i].x + velocities[i].x * kDt) * damping[k].factor;
      positions[i].y = (positions[i].y + velocities[i].y * kDt) * damping[k].factor;
      positions[i].z = (positions[i].z + velocities[i].z * kDt) * damping[k].factor;
    }
    benchmark::ClobberMemory();
  }
  reportPerEntity(state, kEntities / 2);
}

BENCHMARK(BM_View2_PositionVelocity)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Raw2_PositionVelocity)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_View3_SparseDamping)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Raw3_SparseDamping)->Unit(benchmark::kMillisecond);

}  // namespace
