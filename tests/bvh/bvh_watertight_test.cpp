// Watertightness: rays from inside a closed mesh, aimed exactly at its
// vertices and at points on its edges (where non-watertight tests let 1-2 rays
// per million slip through), must all hit, in object space and through an
// instance transform.
#include <gtest/gtest.h>

#include <iostream>
#include <set>

#include "engine/bvh/cpu_traversal.h"
#include "tests/bvh/test_scenes.h"

namespace qlight::bvh::testing {
namespace {

constexpr uint32_t kRaysPerInstance = 600000;

struct Edge {
  uint32_t a, b;
  uint32_t triangles[2];
  uint32_t triangleCount = 0;
};

std::vector<Edge> edgesOf(const Mesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, Edge> edges;
  for (uint32_t t = 0; t < m.triangleCount(); ++t) {
    for (int k = 0; k < 3; ++k) {
      auto key = std::minmax(m.indices[3 * t + k], m.indices[3 * t + (k + 1) % 3]);
      Edge& e = edges[key];
      e.a = key.first;
      e.b = key.second;
      if (e.triangleCount < 2) e.triangles[e.triangleCount] = t;
      e.triangleCount++;
    }
  }
  std::vector<Edge> out;
  for (auto& [key, e] : edges) out.push_back(e);
  return out;
}

// Plain Moller-Trumbore, not watertight: only to show the targets are hard.
bool mollerTrumbore(const glm::vec3& o, const glm::vec3& d, const glm::vec3& p0,
                    const glm::vec3& p1, const glm::vec3& p2) {
  glm::vec3 e1 = p1 - p0, e2 = p2 - p0;
  glm::vec3 pv = glm::cross(d, e2);
  float det = glm::dot(e1, pv);
  if (det == 0.0f) return false;
  float inv = 1.0f / det;
  glm::vec3 tv = o - p0;
  float u = glm::dot(tv, pv) * inv;
  if (u < 0.0f || u > 1.0f) return false;
  glm::vec3 qv = glm::cross(tv, e1);
  float v = glm::dot(d, qv) * inv;
  if (v < 0.0f || u + v > 1.0f) return false;
  return glm::dot(e2, qv) * inv > 0.0f;
}

struct Leaks {
  uint32_t rays = 0;
  uint32_t closestMisses = 0;
  uint32_t anyMisses = 0;
  uint32_t mollerTrumboreLeaks = 0;  // informational
};

// Rays from random points inside (a box of half-size `inner` around the
// centre, or the centre itself) to vertices, edge midpoints and random edge
// points of `mesh`, in the space of instance `instance`.
Leaks shootAtVerticesAndEdges(const Mesh& mesh, const SceneBvh& bvh,
                              const glm::mat4& worldFromObject, float inner, uint64_t seed) {
  CpuBvhBinding binding(bvh.flat());
  std::vector<Edge> edges = edgesOf(mesh);
  for (const Edge& e : edges) EXPECT_EQ(e.triangleCount, 2u) << "mesh is not closed";
  Random rng(seed);
  Leaks leaks;
  bool identity = worldFromObject == glm::mat4(1.0f);
  for (uint32_t i = 0; i < kRaysPerInstance; ++i) {
    glm::vec3 origin =
        (i % 16 == 0) ? glm::vec3(0.0f) : rng.inBox(glm::vec3(-inner), glm::vec3(inner));
    glm::vec3 target;
    const Edge* edge = nullptr;
    switch (i % 3) {
      case 0:
        target = mesh.positions[rng.next() % mesh.positions.size()];
        break;
      case 1:
        edge = &edges[rng.next() % edges.size()];
        target = 0.5f * (mesh.positions[edge->a] + mesh.positions[edge->b]);
        break;
      default:
        edge = &edges[rng.next() % edges.size()];
        target = glm::mix(mesh.positions[edge->a], mesh.positions[edge->b], rng.uniform());
        break;
    }
    glm::vec3 worldOrigin = glm::vec3(worldFromObject * glm::vec4(origin, 1.0f));
    glm::vec3 worldTarget = glm::vec3(worldFromObject * glm::vec4(target, 1.0f));
    glm::vec3 dir = worldTarget - worldOrigin;
    if (i % 2 == 1) dir = glm::normalize(dir);
    shared::BvhHit hit;
    leaks.rays++;
    if (!shared::traceClosest(worldOrigin, dir, 1e30f, hit)) leaks.closestMisses++;
    if (!shared::traceAny(worldOrigin, dir, 1e30f)) leaks.anyMisses++;
    if (identity && edge) {
      bool mt = false;
      for (int k = 0; k < 2; ++k) {
        const uint32_t* tri = &mesh.indices[3 * edge->triangles[k]];
        mt = mt || mollerTrumbore(origin, dir, mesh.positions[tri[0]], mesh.positions[tri[1]],
                                  mesh.positions[tri[2]]);
      }
      leaks.mollerTrumboreLeaks += !mt;
    }
  }
  return leaks;
}

void expectWatertight(const Mesh& mesh, float inner, uint64_t seed, const char* name) {
  for (int variant = 0; variant < 2; ++variant) {
    glm::mat4 worldFromObject = variant == 0
                                    ? glm::mat4(1.0f)
                                    : trs({3.0f, -2.0f, 7.0f}, 0.7f, {1, 2, 3}, {0.6f, 1.7f, 0.9f});
    Scene scene;
    scene.meshes = {mesh};
    scene.instances = {{worldFromObject, 0, 0}};
    SceneBvh bvh = buildScene(scene);
    Leaks leaks = shootAtVerticesAndEdges(mesh, bvh, worldFromObject, inner, seed + variant);
    EXPECT_EQ(leaks.closestMisses, 0u) << name << " variant " << variant << ": of " << leaks.rays;
    EXPECT_EQ(leaks.anyMisses, 0u) << name << " variant " << variant << ": of " << leaks.rays;
    if (variant == 0) {
      std::cout << name << ": " << leaks.rays
                << " rays, 0 expected leaks; plain Moller-Trumbore on "
                << "the two triangles of the aimed edge lets " << leaks.mollerTrumboreLeaks
                << " through\n";
    }
  }
}

TEST(BvhWatertight, IcosphereFromInside) {
  Mesh sphere = icosphere(4);  // 5120 triangles
  ASSERT_EQ(sphere.triangleCount(), 5120u);
  expectWatertight(sphere, 0.5f, 100, "icosphere");
}

TEST(BvhWatertight, GridCubeFromInside) {
  Mesh cube = gridCube(8);  // 768 triangles, faces sharing edge and corner vertices
  ASSERT_EQ(cube.triangleCount(), 768u);
  expectWatertight(cube, 0.95f, 200, "grid cube");
}

}  // namespace
}  // namespace qlight::bvh::testing
