// Structure of the built BVH, read back from the flat texel arrays the GPU
// gets: boxes contain what is below them, every triangle and instance is
// reachable exactly once, depths stay within the traversal stack.
#include <gtest/gtest.h>

#include <bit>
#include <stdexcept>

#include "engine/bvh/cpu_traversal.h"
#include "tests/bvh/brute_force.h"
#include "tests/bvh/test_scenes.h"

namespace qlight::bvh::testing {
namespace {

using shared::kBvhLeafBit;
using shared::kBvhNodeTexels;

uint32_t bitsOf(float f) { return std::bit_cast<uint32_t>(f); }

bool contains(const glm::vec4& lo, const glm::vec4& hi, const glm::vec3& p) {
  return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
}

// Walks one level from `ref` whose box is [lo, hi]; calls leaf(ref, lo, hi)
// for each leaf, checks that child boxes lie inside their parent's box
// (for inner children) and records the deepest leaf (inner nodes above it).
struct Walker {
  const FlatBvh& flat;
  uint32_t nodeBegin, nodeEnd;  // valid inner refs
  uint32_t maxDepth = 0;
  uint32_t innerVisits = 0;
  std::vector<std::string> errors;

  template <typename Leaf>
  void walk(uint32_t ref, glm::vec4 lo, glm::vec4 hi, uint32_t depth, Leaf&& leaf) {
    if (ref & kBvhLeafBit) {
      maxDepth = std::max(maxDepth, depth);
      leaf(ref, lo, hi);
      return;
    }
    if (ref < nodeBegin || ref >= nodeEnd) {
      errors.push_back("inner ref " + std::to_string(ref) + " out of range");
      return;
    }
    innerVisits++;
    const glm::vec4* n = &flat.nodes[ref * kBvhNodeTexels];
    for (int side = 0; side < 2; ++side) {
      glm::vec4 childLo = n[2 * side], childHi = n[2 * side + 1];
      if (!contains(lo, hi, glm::vec3(childLo)) || !contains(lo, hi, glm::vec3(childHi))) {
        errors.push_back("child box of node " + std::to_string(ref) + " leaves its parent's box");
      }
      if (bitsOf(childHi.w) != 0) errors.push_back("reserved lane not zero");
      walk(bitsOf(childLo.w), childLo, childHi, depth + 1, leaf);
    }
  }
};

// Checks one BLAS against its mesh: each kept triangle reached once, inside
// every box on its path, leaves no larger than maxLeaf.
void expectValidBlas(const SceneBvh& bvh, uint32_t index, const Mesh& mesh, uint32_t maxLeaf,
                     uint32_t maxDepth) {
  const FlatBvh& flat = bvh.flat();
  const BlasInfo& info = bvh.blas(index);
  uint32_t kept = 0;
  for (uint32_t t = 0; t < mesh.triangleCount(); ++t) {
    kept += !isDegenerateTriangle(mesh.positions[mesh.indices[3 * t]],
                                  mesh.positions[mesh.indices[3 * t + 1]],
                                  mesh.positions[mesh.indices[3 * t + 2]]);
  }
  ASSERT_EQ(info.triangleCount, kept);
  ASSERT_EQ(info.meshTriangleCount, mesh.triangleCount());

  // Triangle texels equal the mesh's triangles, vertex order kept.
  std::vector<int> seenInMesh(mesh.triangleCount(), 0);
  for (uint32_t i = 0; i < info.triangleCount; ++i) {
    uint32_t slot = info.triangleOffset + i;
    uint32_t original = flat.triangleIndices[slot];
    ASSERT_LT(original, mesh.triangleCount());
    seenInMesh[original]++;
    EXPECT_EQ(bitsOf(flat.triangles[3 * slot].w), original);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(glm::vec3(flat.triangles[3 * slot + k]),
                mesh.positions[mesh.indices[3 * original + k]]);
    }
  }
  for (uint32_t t = 0; t < mesh.triangleCount(); ++t) EXPECT_LE(seenInMesh[t], 1);

  Walker w{flat, info.nodeOffset, info.nodeOffset + info.nodeCount};
  std::vector<int> reached(info.triangleCount, 0);
  auto leaf = [&](uint32_t ref, glm::vec4 lo, glm::vec4 hi) {
    uint32_t first = shared::bvhLeafFirst(ref), count = shared::bvhLeafCount(ref);
    EXPECT_LE(count, maxLeaf);
    for (uint32_t s = first; s < first + count; ++s) {
      ASSERT_GE(s, info.triangleOffset);
      ASSERT_LT(s, info.triangleOffset + info.triangleCount);
      reached[s - info.triangleOffset]++;
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(contains(lo, hi, glm::vec3(flat.triangles[3 * s + k]))) << "triangle " << s;
      }
    }
  };
  w.walk(info.rootRef, glm::vec4(info.bounds.min, 0), glm::vec4(info.bounds.max, 0), 0, leaf);
  EXPECT_TRUE(w.errors.empty()) << w.errors.front();
  EXPECT_EQ(w.innerVisits, info.nodeCount);  // every node reached exactly once (a tree)
  for (uint32_t i = 0; i < info.triangleCount; ++i) ASSERT_EQ(reached[i], 1) << "slot " << i;
  EXPECT_EQ(w.maxDepth, info.depth);
  EXPECT_LE(info.depth, maxDepth);
}

TEST(BvhBuild, BottomLevelStructureForSeveralOptions) {
  Mesh soup = randomSoup(4000, 20);
  addDegenerateTriangles(soup, 300, 21);
  for (uint32_t bins : {16u, 32u}) {
    for (uint32_t leaf : {1u, 4u, 8u}) {
      BuildOptions options;
      options.binCount = bins;
      options.maxLeafSize = leaf;
      SceneBvh bvh;
      bvh.addMesh(soup.positions, soup.indices, options);
      SCOPED_TRACE("bins " + std::to_string(bins) + " leaf " + std::to_string(leaf));
      expectValidBlas(bvh, 0, soup, leaf, shared::kBvhMaxBlasDepth);
      EXPECT_EQ(bvh.blas(0).triangleCount, 4000u);  // the 300 degenerate ones are dropped
    }
  }
}

// The parallel build splits the top sequentially and builds subtrees on worker
// threads: the same tree as one thread, nodes in another order.
TEST(BvhBuild, ParallelBuildMatchesSequential) {
  Mesh soup = randomSoup(kParallelBuildMinPrims + 5000, 26, 40.0f, 0.05f, 1.0f);
  BuildOptions one, two;
  one.threads = 1;
  two.threads = 2;
  SceneBvh a, b;
  a.addMesh(soup.positions, soup.indices, one);
  b.addMesh(soup.positions, soup.indices, two);
  expectValidBlas(b, 0, soup, 4, shared::kBvhMaxBlasDepth);
  EXPECT_EQ(a.blas(0).nodeCount, b.blas(0).nodeCount);
  EXPECT_EQ(a.blas(0).depth, b.blas(0).depth);
  EXPECT_EQ(a.flat().triangleIndices, b.flat().triangleIndices);  // same leaves, same order
  std::vector<Instance> instances = {{glm::mat4(1.0f), 0, 0}};
  a.rebuildTopLevel(instances);
  b.rebuildTopLevel(instances);
  uint32_t differ = 0;
  for (const Ray& ray : randomRays(3000, 27, glm::vec3(0), glm::vec3(40))) {
    shared::BvhHit ha, hb;
    bool fa, fb;
    {
      CpuBvhBinding binding(a.flat());
      fa = shared::traceClosest(ray.origin, ray.dir, 1e30f, ha);
    }
    {
      CpuBvhBinding binding(b.flat());
      fb = shared::traceClosest(ray.origin, ray.dir, 1e30f, hb);
    }
    differ += fa != fb || ha.t != hb.t || ha.primitive != hb.primitive;
  }
  EXPECT_EQ(differ, 0u);
}

TEST(BvhBuild, ConcatenatedBlasesAreEachValid) {
  Scene scene = twoRoomScene();
  scene.meshes.push_back(randomSoup(700, 22));
  SceneBvh bvh = buildScene(scene);
  for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
    SCOPED_TRACE("blas " + std::to_string(i));
    expectValidBlas(bvh, i, scene.meshes[i], 4, shared::kBvhMaxBlasDepth);
  }
  EXPECT_EQ(bvh.flat().triangles.size(), 3 * bvh.flat().triangleIndices.size());
}

// Exponentially spaced triangles make binned SAH peel one triangle per level;
// the depth cap must hold anyway (the shader's stack depends on it).
TEST(BvhBuild, DepthCapHoldsOnPathologicalInput) {
  Mesh chain;
  float x = 1.0f;
  for (int i = 0; i < 400; ++i, x *= 1.2f) {
    addTriangle(chain, {x, 0, 0}, {x * 1.05f, 0.1f * x, 0}, {x, 0, 0.1f * x});
  }
  SceneBvh unlimited;
  BuildOptions deep;
  deep.maxDepth = 1000;
  unlimited.addMesh(chain.positions, chain.indices, deep);
  EXPECT_GT(unlimited.blas(0).depth, 12u) << "input not pathological";

  SceneBvh capped;
  capped.addMesh(chain.positions, chain.indices);
  expectValidBlas(capped, 0, chain, 4, shared::kBvhMaxBlasDepth);

  BuildOptions tight;
  tight.maxDepth = 7;  // 400 / 4 = 100 leaves need 7 levels
  SceneBvh tightest;
  tightest.addMesh(chain.positions, chain.indices, tight);
  expectValidBlas(tightest, 0, chain, 4, 7);
  tight.maxDepth = 6;
  SceneBvh tooTight;
  EXPECT_THROW(tooTight.addMesh(chain.positions, chain.indices, tight), std::runtime_error);
}

TEST(BvhBuild, TopLevelStructure) {
  Scene scene = twoRoomScene();
  Random rng(23);
  for (uint32_t i = 0; i < 300; ++i) {
    scene.instances.push_back({trs(rng.inBox(glm::vec3(-20), glm::vec3(20)), rng.uniform(0, 6),
                                   rng.direction(), glm::vec3(rng.uniform(0.1f, 2.0f))),
                               1 + i % 2, 1000 + i});
  }
  SceneBvh bvh = buildScene(scene);
  const FlatBvh& flat = bvh.flat();
  const TopLevelInfo& top = bvh.topLevel();
  ASSERT_EQ(flat.instances.size(), scene.instances.size() * shared::kBvhInstanceTexels);
  ASSERT_EQ(top.hittableInstances, scene.instances.size());

  Walker w{flat, top.nodeOffset, top.nodeOffset + top.nodeCount};
  std::vector<int> reached(scene.instances.size(), 0);
  auto leaf = [&](uint32_t ref, glm::vec4 lo, glm::vec4 hi) {
    uint32_t i = shared::bvhTlasLeafInstance(ref);
    ASSERT_LT(i, scene.instances.size());
    reached[i]++;
    const Mesh& mesh = scene.meshes[scene.instances[i].blas];
    for (const glm::vec3& p : mesh.positions) {  // every vertex, transformed, inside the box
      glm::vec3 q = glm::vec3(glm::dmat4(scene.instances[i].worldFromObject) * glm::dvec4(p, 1.0));
      EXPECT_TRUE(contains(lo, hi, q)) << "instance " << i;
    }
  };
  w.walk(top.rootRef, glm::vec4(top.bounds.min, 0), glm::vec4(top.bounds.max, 0), 0, leaf);
  EXPECT_TRUE(w.errors.empty()) << w.errors.front();
  EXPECT_EQ(w.innerVisits, top.nodeCount);
  for (int r : reached) EXPECT_EQ(r, 1);
  EXPECT_LE(top.depth, shared::kBvhMaxTlasDepth);

  // Instance texels: both transforms as rows, inverse of each other, and the info texel.
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const glm::vec4* t = &flat.instances[i * shared::kBvhInstanceTexels];
    glm::mat4 objectFromWorld(1.0f), worldFromObject(1.0f);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) {
        objectFromWorld[c][r] = t[shared::kBvhInstanceObjectFromWorld + r][c];
        worldFromObject[c][r] = t[shared::kBvhInstanceWorldFromObject + r][c];
      }
    }
    EXPECT_EQ(worldFromObject, scene.instances[i].worldFromObject);
    glm::mat4 product = objectFromWorld * worldFromObject;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(product[c][r], c == r ? 1.0f : 0.0f, 1e-4f);
    const glm::vec4& info = t[shared::kBvhInstanceInfo];
    const BlasInfo& blas = bvh.blas(scene.instances[i].blas);
    EXPECT_EQ(bitsOf(info.x), blas.rootRef);
    EXPECT_EQ(bitsOf(info.y), blas.triangleOffset);
    EXPECT_EQ(bitsOf(info.z), scene.instances[i].customIndex);
    EXPECT_EQ(bitsOf(info.w), scene.instances[i].blas);
    EXPECT_EQ(t[7], glm::vec4(0.0f));
  }

  // Header.
  const glm::vec4* h = &flat.nodes[0];
  EXPECT_EQ(bitsOf(h[0].x), top.rootRef);
  EXPECT_EQ(bitsOf(h[0].y), scene.instances.size());
  EXPECT_EQ(bitsOf(h[0].z), bvh.topLevelNodeOffset());
  EXPECT_EQ(bitsOf(h[0].w), flat.nodes.size() / kBvhNodeTexels);
  EXPECT_EQ(glm::vec3(h[1]), top.bounds.min);
  EXPECT_EQ(glm::vec3(h[2]), top.bounds.max);
  EXPECT_EQ(bitsOf(h[1].w), bvh.blasCount());
  EXPECT_EQ(bitsOf(h[2].w), flat.triangleIndices.size());
  EXPECT_EQ(flat.nodes.size(), (top.nodeOffset + top.nodeCount) * kBvhNodeTexels);
}

TEST(BvhBuild, RejectsBadInput) {
  std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<uint32_t> outOfRange = {0, 1, 3};
  std::vector<uint32_t> notTriplets = {0, 1};
  SceneBvh bvh;
  EXPECT_THROW(bvh.addMesh(p, outOfRange), std::runtime_error);
  EXPECT_THROW(bvh.addMesh(p, notTriplets), std::runtime_error);
  std::vector<glm::vec3> nan = {{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}};
  EXPECT_THROW(bvh.addMesh(nan, std::vector<uint32_t>{0, 1, 2}), std::runtime_error);
  BuildOptions badLeaf;
  badLeaf.maxLeafSize = 9;
  EXPECT_THROW(bvh.addMesh(p, std::vector<uint32_t>{0, 1, 2}, badLeaf), std::runtime_error);
  EXPECT_EQ(bvh.blasCount(), 0u);
  bvh.addMesh(p, std::vector<uint32_t>{0, 1, 2});
  std::vector<Instance> badBlas = {{glm::mat4(1.0f), 1, 0}};
  EXPECT_THROW(bvh.rebuildTopLevel(badBlas), std::runtime_error);
}

// Empty meshes, meshes of only degenerate triangles, zero-scale instances:
// kept in the instance array, never hit, nothing breaks.
TEST(BvhBuild, UnhittableInstancesAreSkipped) {
  Scene scene;
  Mesh degenerate;
  addDegenerateTriangles(degenerate, 40, 24);
  scene.meshes = {Mesh{}, degenerate, gridCube(1)};
  scene.instances = {{glm::mat4(1.0f), 0, 0},
                     {glm::mat4(1.0f), 1, 1},
                     {glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1)), 2, 2},
                     {glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0)), 2, 3}};
  SceneBvh bvh = buildScene(scene);
  EXPECT_EQ(bvh.topLevel().hittableInstances, 1u);
  EXPECT_EQ(bvh.blas(0).rootRef, 0u);
  EXPECT_EQ(bvh.blas(1).triangleCount, 0u);
  CpuBvhBinding binding(bvh.flat());
  uint32_t hits = 0;
  for (const Ray& ray : randomRays(2000, 25, glm::vec3(-3), glm::vec3(8, 3, 3))) {
    shared::BvhHit hit, ref;
    bool found = shared::traceClosest(ray.origin, ray.dir, 1e30f, hit);
    bool refFound = bruteClosest(scene, ray.origin, ray.dir, 1e30f, ref);
    ASSERT_EQ(compareHits(found, hit, refFound, ref), "");
    if (found) {
      EXPECT_EQ(hit.instance, 3u);
      hits++;
    }
  }
  EXPECT_GT(hits, 50u);
}

// One triangle: both levels' roots are leaves (no inner node at all).
TEST(BvhBuild, SingleTriangleSingleInstance) {
  Scene scene;
  scene.meshes = {Mesh{}};
  addTriangle(scene.meshes[0], {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  scene.instances = {{glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -2)), 0, 7}};
  SceneBvh bvh = buildScene(scene);
  EXPECT_TRUE(bvh.blas(0).rootRef & kBvhLeafBit);
  EXPECT_TRUE(bvh.topLevel().rootRef & kBvhLeafBit);
  EXPECT_EQ(bvh.topLevel().nodeCount, 0u);
  CpuBvhBinding binding(bvh.flat());
  shared::BvhHit hit;
  ASSERT_TRUE(shared::traceClosest({0.25f, 0.5f, 0}, {0, 0, -1}, 1e30f, hit));
  EXPECT_FLOAT_EQ(hit.t, 2.0f);
  EXPECT_FLOAT_EQ(hit.u, 0.25f);
  EXPECT_FLOAT_EQ(hit.v, 0.5f);
  EXPECT_EQ(hit.instance, 0u);
  EXPECT_EQ(hit.primitive, 0u);
  EXPECT_FALSE(shared::traceClosest({0.75f, 0.5f, 0}, {0, 0, -1}, 1e30f, hit));
  EXPECT_FALSE(shared::traceAny({0.25f, 0.5f, 0}, {0, 0, -1}, 1.999f));
}

TEST(BvhBuild, EmptySceneMissesEverything) {
  SceneBvh bvh;
  CpuBvhBinding binding(bvh.flat());
  shared::BvhHit hit;
  EXPECT_FALSE(shared::traceClosest({0, 0, 0}, {0, 0, 1}, 1e30f, hit));
  EXPECT_EQ(hit.instance, shared::kBvhInvalidIndex);
  Mesh cube = gridCube(1);
  bvh.addMesh(cube.positions, cube.indices);
  bvh.rebuildTopLevel(std::vector<Instance>{{glm::mat4(1.0f), 0, 0}});
  CpuBvhBinding rebound(bvh.flat());
  EXPECT_TRUE(shared::traceAny({0, 0, 0}, {0, 0, 1}, 1e30f));
  bvh.addMesh(cube.positions, cube.indices);  // empties the top level until the next rebuild
  CpuBvhBinding stale(bvh.flat());
  EXPECT_FALSE(shared::traceAny({0, 0, 0}, {0, 0, 1}, 1e30f));
}

// addMeshes builds the trees on two threads; the arrays are the very ones addMesh makes one
// mesh after another (a large mesh, built in parallel itself, among small ones).
TEST(BvhBuild, ParallelMeshBuildsEqualSequentialOnes) {
  std::vector<Mesh> meshes = {randomSoup(3000, 21), gridCube(75), icosphere(3),
                              randomSoup(10, 22),   Mesh{},       randomSoup(5000, 23)};
  SceneBvh sequential, parallel;
  std::vector<MeshInput> inputs;
  for (const Mesh& m : meshes) {
    sequential.addMesh(m.positions, m.indices);
    inputs.push_back({m.positions, m.indices});
  }
  parallel.addMeshes(inputs);
  EXPECT_EQ(parallel.flat().nodes, sequential.flat().nodes);
  EXPECT_EQ(parallel.flat().triangles, sequential.flat().triangles);
  EXPECT_EQ(parallel.flat().triangleIndices, sequential.flat().triangleIndices);
  ASSERT_EQ(parallel.blasCount(), meshes.size());
  Mesh bad = randomSoup(10, 24);
  bad.indices[4] = 1000;
  inputs.push_back({bad.positions, bad.indices});
  SceneBvh failing;
  EXPECT_THROW(failing.addMeshes(inputs), std::runtime_error);
}

}  // namespace
}  // namespace qlight::bvh::testing
