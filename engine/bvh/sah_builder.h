// Binned SAH builder (Wald 2007, "On fast Construction of SAH-based Bounding
// Volume Hierarchies") shared by both levels: BLAS over triangles, TLAS over
// instances. Iterative (an explicit task stack), depth-capped: where an SAH
// split would make a subtree deeper than maxDepth allows, it splits at the
// object median instead, so the shader's fixed stack can never overflow.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/bvh/aabb.h"
#include "shaders/shared/bvh_types.h"

namespace qlight::bvh {

// One primitive's bounds and its index in the caller's list (32 bytes, so the
// partition passes move few cache lines).
struct PrimRef {
  glm::vec3 min;
  uint32_t index;
  glm::vec3 max;
  uint32_t pad = 0;
};

struct BuildOptions {
  uint32_t binCount = 32;                        // 2 .. kMaxBins
  uint32_t maxLeafSize = 4;                      // 1 .. kBvhMaxLeafTriangles
  uint32_t maxDepth = shared::kBvhMaxBlasDepth;  // inner nodes on any root-to-leaf path
  float traversalCost = 1.0f;  // cost of a node visit relative to one primitive test
  uint32_t threads = 2;        // worker threads for inputs of kParallelBuildMinPrims or more
};

inline constexpr uint32_t kParallelBuildMinPrims = 65536;

inline constexpr uint32_t kMaxBins = 64;

// A node as the builder makes it: both children's boxes and refs. A ref is a
// local node index (the root is node 0), or kBvhLeafBit | first << 3 |
// (count - 1) with first/count a range of the reordered PrimRefs.
struct BuildNode {
  Aabb box[2];
  uint32_t child[2];
};

struct BuiltTree {
  std::vector<BuildNode> nodes;
  uint32_t rootRef = 0;  // node 0, or a leaf when the whole input fits one leaf
  Aabb bounds;
  uint32_t depth = 0;  // most inner nodes on a root-to-leaf path
};

// Reorders prims into leaf order. prims must be non-empty, with finite boxes,
// and at most kBvhMaxTriangles of them; throws std::runtime_error otherwise.
BuiltTree buildSah(std::vector<PrimRef>& prims, const BuildOptions& options);

// Inner levels a balanced (median) split needs to get `count` prims into
// leaves of maxLeafSize: ceil(log2(ceil(count / maxLeafSize))).
uint32_t levelsNeeded(uint32_t count, uint32_t maxLeafSize);

}  // namespace qlight::bvh
