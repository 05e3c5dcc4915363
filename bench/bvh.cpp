// BVH build time (BLAS, TLAS) and single-thread CPU traversal speed of the
// shared traversal code. items_per_second is triangles/s for builds and
// rays/s for traversal.
#include <benchmark/benchmark.h>

#include <cmath>

#include "engine/bvh/cpu_traversal.h"
#include "tests/bvh/test_scenes.h"

namespace {

using namespace qlight::bvh;
using namespace qlight::bvh::testing;

// Terrain: an n x n grid of quads with a smooth height field (structured,
// like real meshes: small triangles, shared vertices).
Mesh terrain(int n) {
  Mesh m;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      float x = 10.0f * i / n, z = 10.0f * j / n;
      m.positions.push_back({x, 0.5f * std::sin(1.3f * x) * std::cos(0.9f * z) + 0.1f * x, z});
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
  }
  return m;
}

const Mesh& buildInput(int kind, int triangles) {
  static std::map<std::pair<int, int>, Mesh> cache;
  auto key = std::make_pair(kind, triangles);
  auto it = cache.find(key);
  if (it == cache.end()) {
    Mesh m = kind == 0 ? randomSoup(triangles, 1, 100.0f, 0.1f, 2.0f)
                       : terrain(static_cast<int>(std::sqrt(triangles / 2.0)));
    it = cache.emplace(key, std::move(m)).first;
  }
  return it->second;
}

void BM_BuildBlas(benchmark::State& state) {
  const Mesh& mesh = buildInput(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  for (auto _ : state) {
    SceneBvh bvh;
    bvh.addMesh(mesh.positions, mesh.indices);
    benchmark::DoNotOptimize(bvh.flat().nodes.data());
  }
  state.SetItemsProcessed(state.iterations() * mesh.triangleCount());
  state.SetLabel(state.range(0) == 0 ? "random soup" : "terrain grid");
}
BENCHMARK(BM_BuildBlas)
    ->Args({0, 100000})
    ->Args({0, 1000000})
    ->Args({1, 100000})
    ->Args({1, 1000000})
    ->UseRealTime()  // the build runs on 2 threads
    ->Unit(benchmark::kMillisecond);

void BM_RebuildTopLevel(benchmark::State& state) {
  Scene scene;
  scene.meshes = {gridCube(2), icosphere(2)};
  Random rng(3);
  for (int64_t i = 0; i < state.range(0); ++i) {
    scene.instances.push_back({trs(rng.inBox(glm::vec3(-50), glm::vec3(50)), rng.uniform(0, 6),
                                   rng.direction(), glm::vec3(rng.uniform(0.2f, 2.0f))),
                               static_cast<uint32_t>(i % 2), static_cast<uint32_t>(i)});
  }
  SceneBvh bvh = buildScene(scene);
  for (auto _ : state) {
    bvh.rebuildTopLevel(scene.instances);
    benchmark::DoNotOptimize(bvh.flat().nodes.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_RebuildTopLevel)->Arg(100)->Arg(10000)->Unit(benchmark::kMicrosecond);

struct TraceSetup {
  Scene scene;
  SceneBvh bvh;
  std::vector<Ray> rays;
};

// 0: the two-room scene (walls + 4 instances, ~750 triangles in all);
// 1: a 100k-triangle random soup; 2: a 100k-triangle terrain under rays from above.
const TraceSetup& traceSetup(int kind) {
  static std::map<int, TraceSetup> cache;
  auto it = cache.find(kind);
  if (it != cache.end()) return it->second;
  TraceSetup s;
  constexpr uint32_t kRays = 1 << 16;
  if (kind == 0) {
    s.scene = twoRoomScene();
    s.rays = randomRays(kRays, 5, glm::vec3(0.01f), glm::vec3(9.99f, 2.99f, 4.99f));
  } else if (kind == 1) {
    s.scene.meshes = {randomSoup(100000, 6, 100.0f, 0.2f, 2.0f)};
    s.scene.instances = {{glm::mat4(1.0f), 0, 0}};
    s.rays = randomRays(kRays, 7, glm::vec3(0.0f), glm::vec3(100.0f));
  } else {
    s.scene.meshes = {terrain(224)};
    s.scene.instances = {{glm::mat4(1.0f), 0, 0}};
    s.rays = randomRays(kRays, 8, glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(10.0f, 4.0f, 10.0f));
    for (Ray& r : s.rays) r.dir.y = -std::abs(r.dir.y);
  }
  s.bvh = buildScene(s.scene);
  return cache.emplace(kind, std::move(s)).first->second;
}

const char* traceLabel(int kind) {
  return kind == 0 ? "two rooms" : (kind == 1 ? "soup 100k" : "terrain 100k");
}

void BM_TraceClosest(benchmark::State& state) {
  const TraceSetup& s = traceSetup(static_cast<int>(state.range(0)));
  CpuBvhBinding binding(s.bvh.flat());
  uint32_t hits = 0;
  for (auto _ : state) {
    for (const Ray& r : s.rays) {
      qlight::shared::BvhHit hit;
      hits += qlight::shared::traceClosest(r.origin, r.dir, 1e30f, hit);
    }
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * s.rays.size());
  state.SetLabel(traceLabel(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_TraceClosest)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_TraceAny(benchmark::State& state) {
  const TraceSetup& s = traceSetup(static_cast<int>(state.range(0)));
  CpuBvhBinding binding(s.bvh.flat());
  uint32_t hits = 0;
  for (auto _ : state) {
    for (const Ray& r : s.rays) hits += qlight::shared::traceAny(r.origin, r.dir, 1e30f);
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * s.rays.size());
  state.SetLabel(traceLabel(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_TraceAny)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
