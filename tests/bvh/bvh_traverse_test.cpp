// The shared traversal (the shader's code, compiled as C++) against brute force
// over every triangle of every instance, on seeded random rays.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "engine/bvh/cpu_traversal.h"
#include "tests/bvh/brute_force.h"
#include "tests/bvh/test_scenes.h"

namespace qlight::bvh::testing {
namespace {

constexpr float kFar = 1e30f;

struct Agreement {
  uint32_t rays = 0;
  uint32_t hits = 0;
  uint32_t mismatches = 0;
  std::string first;
};

// Closest hit and any hit for every ray, both against the reference.
Agreement compareWithBruteForce(const Scene& scene, const SceneBvh& bvh,
                                const std::vector<Ray>& rays, float tMax = kFar) {
  CpuBvhBinding binding(bvh.flat());
  Agreement a;
  for (const Ray& ray : rays) {
    shared::BvhHit hit, ref;
    bool found = shared::traceClosest(ray.origin, ray.dir, tMax, hit);
    bool refFound = bruteClosest(scene, ray.origin, ray.dir, tMax, ref);
    bool any = shared::traceAny(ray.origin, ray.dir, tMax);
    std::string diff = compareHits(found, hit, refFound, ref);
    if (diff.empty() && any != refFound) diff = "traceAny disagrees";
    a.rays++;
    a.hits += refFound;
    if (!diff.empty()) {
      if (a.mismatches++ == 0) a.first = diff;
    }
  }
  return a;
}

#define EXPECT_AGREES(a)                                                \
  EXPECT_EQ((a).mismatches, 0u) << (a).mismatches << " of " << (a).rays \
                                << " rays differ; first: " << (a).first;

TEST(BvhTraverse, RandomSoupMatchesBruteForce) {
  Scene scene;
  scene.meshes = {randomSoup(3000, 1)};
  scene.instances = {{glm::mat4(1.0f), 0, 0}};
  SceneBvh bvh = buildScene(scene);
  // Origins inside the soup and around it.
  Agreement a =
      compareWithBruteForce(scene, bvh, randomRays(5000, 2, glm::vec3(-2), glm::vec3(12)));
  EXPECT_AGREES(a);
  EXPECT_GT(a.hits, 1000u);  // not an empty test: many rays hit something
}

TEST(BvhTraverse, InstancedSoupsMatchBruteForce) {
  const Scene scene = instancedSoups();
  SceneBvh bvh = buildScene(scene);
  Agreement a =
      compareWithBruteForce(scene, bvh, randomRays(4000, 6, glm::vec3(-12), glm::vec3(12)));
  EXPECT_AGREES(a);
  EXPECT_GT(a.hits, 300u);
}

TEST(BvhTraverse, TwoRoomSceneMatchesBruteForce) {
  Scene scene = twoRoomScene();
  SceneBvh bvh = buildScene(scene);
  // From inside the rooms: every ray must hit (the box is closed).
  Agreement inside = compareWithBruteForce(
      scene, bvh, randomRays(8000, 7, glm::vec3(0.01f), glm::vec3(9.99f, 2.99f, 4.99f)));
  EXPECT_AGREES(inside);
  EXPECT_EQ(inside.hits, inside.rays);
  // From around the box, so the outside faces and misses are covered too.
  Agreement around =
      compareWithBruteForce(scene, bvh, randomRays(4000, 8, glm::vec3(-3), glm::vec3(13, 6, 8)));
  EXPECT_AGREES(around);
}

TEST(BvhTraverse, RaysThroughTheDoorReachTheOtherRoom) {
  Scene scene = twoRoomScene();
  SceneBvh bvh = buildScene(scene);
  CpuBvhBinding binding(bvh.flat());
  Random rng(9);
  for (int i = 0; i < 200; ++i) {
    glm::vec3 origin(rng.uniform(0.5f, 4.0f), rng.uniform(0.2f, 1.8f), rng.uniform(2.0f, 3.0f));
    glm::vec3 door(5.0f, rng.uniform(0.1f, 1.9f), rng.uniform(2.45f, 2.55f));
    shared::BvhHit hit, ref;
    bool found = shared::traceClosest(origin, door - origin, kFar, hit);
    bool refFound = bruteClosest(scene, origin, door - origin, kFar, ref);
    ASSERT_EQ(compareHits(found, hit, refFound, ref), "");
    if (hit.instance == 0) {  // the rooms, not an instance in the way
      EXPECT_GT(origin.x + hit.t * (door.x - origin.x), 5.0f) << "stopped at the dividing wall";
    }
  }
}

TEST(BvhTraverse, DegenerateTrianglesMixedInMatchBruteForce) {
  Scene scene;
  Mesh soup = randomSoup(2000, 10);
  addDegenerateTriangles(soup, 500, 11);
  Mesh rooms = twoRooms();
  addDegenerateTriangles(rooms, 100, 12);
  // Slivers: valid but nearly zero area, mixed with the degenerate ones.
  Random rng(13);
  for (int i = 0; i < 200; ++i) {
    glm::vec3 a = rng.inBox(glm::vec3(0), glm::vec3(10));
    addTriangle(soup, a, a + glm::vec3(1, 1e-4f, 0), a + glm::vec3(2, 0, 1e-4f));
  }
  scene.meshes = {soup, rooms};
  scene.instances = {{glm::mat4(1.0f), 0, 0},
                     {trs({0.5f, 0, 0}, 0.2f, {0, 1, 0}, {1, 1, 1}), 1, 1}};
  SceneBvh bvh = buildScene(scene);
  Agreement a =
      compareWithBruteForce(scene, bvh, randomRays(5000, 14, glm::vec3(-1), glm::vec3(11)));
  EXPECT_AGREES(a);
}

// traceAny(tMax) must say whether the closest hit lies before tMax, and
// traceClosest with a shorter tMax must equal brute force with that tMax.
TEST(BvhTraverse, TMaxBoundsBothQueries) {
  Scene scene = twoRoomScene();
  SceneBvh bvh = buildScene(scene);
  CpuBvhBinding binding(bvh.flat());
  std::vector<Ray> rays = randomRays(3000, 15, glm::vec3(0.01f), glm::vec3(9.99f, 2.99f, 4.99f));
  uint32_t mismatches = 0;
  std::string first;
  for (const Ray& ray : rays) {
    shared::BvhHit ref;
    ASSERT_TRUE(bruteClosest(scene, ray.origin, ray.dir, kFar, ref));
    float t = ref.t;
    float justAfter = std::nextafter(t, kFar);
    struct Case {
      float tMax;
      bool expectAny;
    } cases[] = {{0.5f * t, false}, {t, false}, {justAfter, true}, {2.0f * t, true}};
    for (const Case& c : cases) {
      bool any = shared::traceAny(ray.origin, ray.dir, c.tMax);
      shared::BvhHit hit, bounded;
      bool found = shared::traceClosest(ray.origin, ray.dir, c.tMax, hit);
      bool refFound = bruteClosest(scene, ray.origin, ray.dir, c.tMax, bounded);
      std::string diff = compareHits(found, hit, refFound, bounded);
      if (any != c.expectAny) diff += " traceAny wrong at tMax/t=" + std::to_string(c.tMax / t);
      if (found != c.expectAny)
        diff += " traceClosest wrong at tMax/t=" + std::to_string(c.tMax / t);
      if (!found && hit.t != c.tMax) diff += " a miss must report t = tMax";
      if (!diff.empty() && mismatches++ == 0) {
        char buf[256];
        std::snprintf(buf, sizeof buf, " [o=(%.9g %.9g %.9g) d=(%.9g %.9g %.9g) t=%.9g tMax=%.9g]",
                      ray.origin.x, ray.origin.y, ray.origin.z, ray.dir.x, ray.dir.y, ray.dir.z, t,
                      c.tMax);
        first = diff + buf;
      }
    }
  }
  EXPECT_EQ(mismatches, 0u) << first;
}

TEST(BvhTraverse, TopLevelRebuildAfterMovingAnInstance) {
  Scene scene = twoRoomScene();
  SceneBvh bvh = buildScene(scene);
  const uint32_t blasTexels = bvh.topLevelNodeOffset() * shared::kBvhNodeTexels;
  std::vector<glm::vec4> blasNodes(bvh.flat().nodes.begin() + 4,
                                   bvh.flat().nodes.begin() + blasTexels);
  std::vector<glm::vec4> triangles = bvh.flat().triangles;

  // Move the sphere from room 2 into room 1 and spin the cube.
  scene.instances[3].worldFromObject = trs({3.0f, 1.5f, 1.0f}, 0.4f, {0, 1, 1}, {0.5f, 0.9f, 0.6f});
  scene.instances[1].worldFromObject = trs({2.0f, 1.0f, 3.0f}, 1.3f, {1, 0, 0}, {0.5f, 1.2f, 0.3f});
  bvh.rebuildTopLevel(scene.instances);

  // The bottom levels are untouched: only the top level was rebuilt.
  EXPECT_EQ(bvh.topLevelNodeOffset() * shared::kBvhNodeTexels, blasTexels);
  EXPECT_TRUE(std::equal(blasNodes.begin(), blasNodes.end(), bvh.flat().nodes.begin() + 4));
  EXPECT_EQ(bvh.flat().triangles, triangles);

  Agreement a = compareWithBruteForce(
      scene, bvh, randomRays(6000, 16, glm::vec3(0.01f), glm::vec3(9.99f, 2.99f, 4.99f)));
  EXPECT_AGREES(a);

  // A ray at the sphere's new centre hits it; one at its old centre does not.
  CpuBvhBinding binding(bvh.flat());
  shared::BvhHit hit;
  glm::vec3 origin(0.5f, 1.5f, 1.0f);
  ASSERT_TRUE(shared::traceClosest(origin, glm::vec3(3.0f, 1.5f, 1.0f) - origin, kFar, hit));
  EXPECT_EQ(hit.instance, 3u);
  origin = glm::vec3(9.5f, 1.2f, 2.5f);
  ASSERT_TRUE(shared::traceClosest(origin, glm::vec3(7.5f, 1.2f, 2.5f) - origin, kFar, hit));
  EXPECT_NE(hit.instance, 3u);
}

TEST(BvhTraverse, UnnormalizedDirectionsGiveScaledT) {
  Scene scene = twoRoomScene();
  SceneBvh bvh = buildScene(scene);
  CpuBvhBinding binding(bvh.flat());
  for (const Ray& ray : randomRays(500, 17, glm::vec3(0.5f), glm::vec3(9.5f, 2.5f, 4.5f))) {
    shared::BvhHit unit, scaled;
    ASSERT_TRUE(shared::traceClosest(ray.origin, ray.dir, kFar, unit));
    ASSERT_TRUE(shared::traceClosest(ray.origin, 4.0f * ray.dir, kFar, scaled));
    EXPECT_NEAR(scaled.t * 4.0f, unit.t, 1e-5f * unit.t);
    EXPECT_EQ(scaled.instance, unit.instance);
  }
}

}  // namespace
}  // namespace qlight::bvh::testing
