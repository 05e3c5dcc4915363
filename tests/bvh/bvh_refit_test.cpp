// SceneBvh::refitMesh: a BLAS whose vertices moved (a skinned or morphed mesh) traverses
// exactly like brute force over the moved triangles, whatever the motion did to its tree.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/bvh/cpu_traversal.h"
#include "tests/bvh/brute_force.h"
#include "tests/bvh/test_scenes.h"

namespace qlight::bvh::testing {
namespace {

constexpr float kFar = 1e30f;

// A twist about y (angle grows with height) and a bulge: what a joint does to a limb.
Mesh twisted(const Mesh& mesh, float turns) {
  Mesh out = mesh;
  for (glm::vec3& p : out.positions) {
    const float a = turns * 3.14159265f * p.y, c = std::cos(a), s = std::sin(a);
    const float bulge = 1.0f + 0.3f * std::cos(1.5f * p.y);
    p = glm::vec3(bulge * (c * p.x + s * p.z), 1.2f * p.y, bulge * (-s * p.x + c * p.z));
  }
  return out;
}

uint32_t mismatches(const Scene& scene, const SceneBvh& bvh, const std::vector<Ray>& rays,
                    uint32_t& hits, std::string& first) {
  CpuBvhBinding binding(bvh.flat());
  uint32_t bad = 0;
  hits = 0;
  for (const Ray& ray : rays) {
    shared::BvhHit hit, ref;
    const bool found = shared::traceClosest(ray.origin, ray.dir, kFar, hit);
    const bool refFound = bruteClosest(scene, ray.origin, ray.dir, kFar, ref);
    std::string diff = compareHits(found, hit, refFound, ref);
    if (diff.empty() && shared::traceAny(ray.origin, ray.dir, kFar) != refFound)
      diff = "traceAny disagrees";
    hits += refFound;
    if (!diff.empty() && bad++ == 0) first = diff;
  }
  return bad;
}

// Built on the rest pose, refitted to the twisted one, then compared with brute force on the
// twisted mesh, for a mesh big enough for the parallel build (its subtrees are appended out
// of order) and two instances of it, one mirrored.
TEST(BvhRefit, RefittedMeshMatchesBruteForceOnTheDeformedTriangles) {
  const Mesh rest = gridCube(76);  // 69,312 triangles: the two-thread build
  ASSERT_GE(rest.triangleCount(), kParallelBuildMinPrims);
  Scene scene;
  scene.meshes = {rest};
  scene.instances = {
      {glm::mat4(1.0f), 0, 0},
      {trs(glm::vec3(4, 0, 0), 0.7f, glm::vec3(0, 1, 0), glm::vec3(1, -1, 1)), 0, 1}};
  SceneBvh bvh = buildScene(scene);
  for (float turns : {0.25f, 0.75f}) {
    SCOPED_TRACE("turns " + std::to_string(turns));
    scene.meshes[0] = twisted(rest, turns);
    bvh.refitMesh(0, scene.meshes[0].positions, scene.meshes[0].indices);
    bvh.rebuildTopLevel(scene.instances);
    uint32_t hits = 0;
    std::string first;
    const uint32_t bad =
        mismatches(scene, bvh, randomRays(600, 7, glm::vec3(-3), glm::vec3(7)), hits, first);
    EXPECT_EQ(bad, 0u) << "first: " << first;
    EXPECT_GT(hits, 40u);  // random rays around two cubes: about one in ten hits
    // The refitted root holds every moved vertex.
    for (const glm::vec3& p : scene.meshes[0].positions)
      ASSERT_TRUE(bvh.blas(0).bounds.contains(Aabb{p, p}));
  }
}

// A soup whose triangles all jump elsewhere: the worst case for a refit's tree, still exact.
TEST(BvhRefit, ScrambledSoupStillMatchesBruteForce) {
  Scene scene;
  scene.meshes = {randomSoup(2000, 11)};
  scene.instances = {{glm::mat4(1.0f), 0, 0}};
  SceneBvh bvh = buildScene(scene);
  Random rng(12);
  for (glm::vec3& p : scene.meshes[0].positions)
    p = glm::vec3(p.z, p.x, p.y) + rng.inBox(glm::vec3(-1), glm::vec3(1));
  bvh.refitMesh(0, scene.meshes[0].positions, scene.meshes[0].indices);
  bvh.rebuildTopLevel(scene.instances);
  uint32_t hits = 0;
  std::string first;
  EXPECT_EQ(mismatches(scene, bvh, randomRays(3000, 13, glm::vec3(-2), glm::vec3(12)), hits, first),
            0u)
      << first;
  EXPECT_GT(hits, 500u);
}

TEST(BvhRefit, OtherIndicesOrNonFinitePositionsAreRefused) {
  Mesh mesh = icosphere(1);
  SceneBvh bvh;
  bvh.addMesh(mesh.positions, mesh.indices);
  std::vector<uint32_t> fewer(mesh.indices.begin(), mesh.indices.end() - 3);
  EXPECT_THROW(bvh.refitMesh(0, mesh.positions, fewer), std::runtime_error);
  mesh.positions[0].x = std::nanf("");
  EXPECT_THROW(bvh.refitMesh(0, mesh.positions, mesh.indices), std::runtime_error);
}

}  // namespace
}  // namespace qlight::bvh::testing
