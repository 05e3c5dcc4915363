// The merged BLAS (fixed instances' triangles copied to world space into one tree) against
// brute force over the instances in object space: the same instance and triangle, with t
// and the barycentrics equal up to the rounding of the copy; and when it is built again.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/bvh/cpu_traversal.h"
#include "tests/bvh/brute_force.h"
#include "tests/bvh/test_scenes.h"

namespace qlight::bvh::testing {
namespace {

constexpr float kFar = 1e30f;
// The copy rounds each world-space vertex once, by about 2^-24 of its coordinates; t and
// the hit point move by that much. The bounds below are 100x that, while a wrong triangle,
// instance or barycentrics, or a t from another surface, is far outside them.
constexpr float kRounding = 100.0f / (1 << 24);

struct Agreement {
  uint32_t rays = 0;
  uint32_t hits = 0;
  uint32_t mismatches = 0;
  std::string first;
};

// The point a hit names: its barycentrics on its triangle, in world space.
glm::vec3 pointOf(const Scene& scene, const shared::BvhHit& hit) {
  const Instance& inst = scene.instances[hit.instance];
  const Mesh& mesh = scene.meshes[inst.blas];
  glm::vec3 p[3];
  for (int k = 0; k < 3; ++k)
    p[k] = glm::vec3(inst.worldFromObject *
                     glm::vec4(mesh.positions[mesh.indices[3 * hit.primitive + k]], 1.0f));
  return (1.0f - hit.u - hit.v) * p[0] + hit.u * p[1] + hit.v * p[2];
}

// Agrees when both miss, or both hit at the same t (up to the copy's rounding) and the
// reported instance, triangle and barycentrics name the point on the ray at that t (the
// reference's triangle, or a neighbour at a shared edge).
std::string compareNear(const Scene& scene, const Ray& ray, bool found, const shared::BvhHit& hit,
                        bool refFound, const shared::BvhHit& ref) {
  auto describe = [](bool f, const shared::BvhHit& h) {
    return f ? "hit(t=" + std::to_string(h.t) + " inst=" + std::to_string(h.instance) +
                   " prim=" + std::to_string(h.primitive) + ")"
             : std::string("miss");
  };
  const std::string diff = describe(found, hit) + " vs reference " + describe(refFound, ref);
  if (found != refFound) return diff;
  if (!found) return "";
  const glm::vec3 onRay = ray.origin + ref.t * ray.dir;
  const float scale = std::max(1.0f, std::max(glm::length(ray.origin), glm::length(onRay)));
  if (std::abs(hit.t - ref.t) > kRounding * scale) return diff;
  if (hit.instance >= scene.instances.size() ||
      hit.primitive >= scene.meshes[scene.instances[hit.instance].blas].triangleCount())
    return diff + " (no such triangle)";
  const float off = glm::length(pointOf(scene, hit) - onRay);
  if (off > kRounding * scale)
    return diff + " (its barycentrics name a point " + std::to_string(off) + " off the ray)";
  return "";
}

Agreement compare(const Scene& scene, const SceneBvh& bvh, const std::vector<Ray>& rays) {
  CpuBvhBinding binding(bvh.flat());
  Agreement a;
  for (const Ray& ray : rays) {
    shared::BvhHit hit, ref;
    const bool found = shared::traceClosest(ray.origin, ray.dir, kFar, hit);
    const bool refFound = bruteClosest(scene, ray.origin, ray.dir, kFar, ref);
    std::string diff = compareNear(scene, ray, found, hit, refFound, ref);
    if (diff.empty() && shared::traceAny(ray.origin, ray.dir, kFar) != refFound)
      diff = "traceAny disagrees";
    a.rays++;
    a.hits += refFound;
    if (!diff.empty() && a.mismatches++ == 0) a.first = diff;
  }
  return a;
}

#define EXPECT_AGREES(a)                                                \
  EXPECT_EQ((a).mismatches, 0u) << (a).mismatches << " of " << (a).rays \
                                << " rays differ; first: " << (a).first;

Scene allFixed(Scene scene) {
  for (Instance& i : scene.instances) i.fixed = true;
  return scene;
}

TEST(BvhMerged, TwoRoomSceneMatchesBruteForce) {
  const Scene scene = allFixed(twoRoomScene());
  const SceneBvh bvh = buildScene(scene);
  EXPECT_EQ(bvh.merged().instances, 5u);
  EXPECT_NE(bvh.merged().rootRef, 0u);
  EXPECT_EQ(bvh.topLevel().nodeCount, 0u);  // one leaf: the merged BLAS's instance
  // Inside the closed rooms every ray must hit: the copy keeps shared edges closed.
  const Agreement inside =
      compare(scene, bvh, randomRays(8000, 7, glm::vec3(0.01f), glm::vec3(9.99f, 2.99f, 4.99f)));
  EXPECT_AGREES(inside);
  EXPECT_EQ(inside.hits, inside.rays);
  const Agreement around =
      compare(scene, bvh, randomRays(4000, 8, glm::vec3(-3), glm::vec3(13, 6, 8)));
  EXPECT_AGREES(around);
  EXPECT_GT(around.hits, 500u);
}

TEST(BvhMerged, FixedAndMovingInstancesTogether) {
  Scene scene = instancedSoups();
  for (uint32_t i = 0; i < scene.instances.size(); ++i) scene.instances[i].fixed = i % 4 != 0;
  SceneBvh bvh = buildScene(scene);
  EXPECT_EQ(bvh.merged().instances, 9u);
  EXPECT_EQ(bvh.merged().builds, 1u);
  const std::vector<Ray> rays = randomRays(4000, 6, glm::vec3(-12), glm::vec3(12));
  Agreement a = compare(scene, bvh, rays);
  EXPECT_AGREES(a);
  EXPECT_GT(a.hits, 300u);

  // Moving an instance that is not fixed rebuilds the top level only.
  const uint64_t triangles = bvh.trianglesVersion();
  scene.instances[4].worldFromObject = trs({1, 2, 3}, 0.5f, {0, 1, 0}, glm::vec3(0.8f));
  bvh.rebuildTopLevel(scene.instances);
  EXPECT_EQ(bvh.merged().builds, 1u);
  EXPECT_EQ(bvh.trianglesVersion(), triangles);
  a = compare(scene, bvh, rays);
  EXPECT_AGREES(a);

  // A fixed instance that moves after all, or stops being fixed, builds the merged BLAS again.
  scene.instances[1].worldFromObject = trs({-2, 0, 1}, 1.0f, {1, 0, 0}, glm::vec3(1.2f));
  bvh.rebuildTopLevel(scene.instances);
  EXPECT_EQ(bvh.merged().builds, 2u);
  EXPECT_NE(bvh.trianglesVersion(), triangles);
  a = compare(scene, bvh, rays);
  EXPECT_AGREES(a);
  scene.instances[2].fixed = false;
  bvh.rebuildTopLevel(scene.instances);
  EXPECT_EQ(bvh.merged().builds, 3u);
  EXPECT_EQ(bvh.merged().instances, 8u);
  a = compare(scene, bvh, rays);
  EXPECT_AGREES(a);
}

TEST(BvhMerged, RefittingAMergedMeshBuildsItAgain) {
  Scene scene = allFixed(twoRoomScene());
  SceneBvh bvh = buildScene(scene);
  for (glm::vec3& p : scene.meshes[2].positions) p *= 1.3f;  // the sphere grows
  bvh.refitMesh(2, scene.meshes[2].positions, scene.meshes[2].indices);
  bvh.rebuildTopLevel(scene.instances);
  EXPECT_EQ(bvh.merged().builds, 2u);
  const Agreement a =
      compare(scene, bvh, randomRays(4000, 9, glm::vec3(0.01f), glm::vec3(9.99f, 2.99f, 4.99f)));
  EXPECT_AGREES(a);
}

TEST(BvhMerged, SharedMeshesOnlyWithinTheBudget) {
  Scene scene = allFixed(twoRoomScene());  // mesh 0 once; meshes 1 and 2 twice each
  SceneBvh bvh;
  for (const Mesh& m : scene.meshes) bvh.addMesh(m.positions, m.indices);
  const uint32_t rooms = bvh.blas(0).triangleCount, cube = bvh.blas(1).triangleCount;
  bvh.setMaxMergedTriangles(rooms + 2 * cube);  // both cubes fit, no sphere does
  bvh.rebuildTopLevel(scene.instances);
  EXPECT_EQ(bvh.merged().instances, 3u);
  EXPECT_EQ(bvh.merged().triangleCount, rooms + 2 * cube);
  EXPECT_GT(bvh.topLevel().nodeCount, 0u);  // the spheres stay instances of their BLAS
  const Agreement a =
      compare(scene, bvh, randomRays(4000, 10, glm::vec3(0.01f), glm::vec3(9.99f, 2.99f, 4.99f)));
  EXPECT_AGREES(a);
}

TEST(BvhMerged, OneFixedInstanceIsNotCopied) {
  Scene scene;
  scene.meshes = {randomSoup(500, 11)};
  scene.instances = {{glm::mat4(1.0f), 0, 0, true}};
  const SceneBvh bvh = buildScene(scene);
  EXPECT_EQ(bvh.merged().rootRef, 0u);
  EXPECT_EQ(bvh.flat().instances.size(), shared::kBvhInstanceTexels);  // no extra instance
}

TEST(BvhMerged, AddingAMeshDropsTheMergedCopy) {
  Scene scene = allFixed(twoRoomScene());
  SceneBvh bvh = buildScene(scene);
  const size_t meshTriangles = bvh.blas(2).triangleOffset + bvh.blas(2).triangleCount;
  ASSERT_GT(bvh.flat().triangleIndices.size(), meshTriangles);
  scene.meshes.push_back(randomSoup(50, 12, 1.0f));
  scene.instances.push_back({trs({5, 1, 2}, 0.0f, {0, 1, 0}, glm::vec3(1)), 3, 105, true});
  bvh.addMesh(scene.meshes[3].positions, scene.meshes[3].indices);
  EXPECT_EQ(bvh.blas(3).triangleOffset, meshTriangles);  // after the meshes, not the copy
  bvh.rebuildTopLevel(scene.instances);
  EXPECT_EQ(bvh.merged().instances, 6u);
  const Agreement a = compare(scene, bvh, randomRays(4000, 13, glm::vec3(-3), glm::vec3(13, 6, 8)));
  EXPECT_AGREES(a);
}

}  // namespace
}  // namespace qlight::bvh::testing
