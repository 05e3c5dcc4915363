#include "engine/bvh/sah_builder.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>

namespace qlight::bvh {
namespace {

using shared::kBvhLeafBit;
using shared::kBvhLeafCountBits;

constexpr uint32_t kRootSlot = 0xffffffffu;

// Centroids are kept doubled (min + max) to save a multiply per primitive.
glm::vec3 doubledCentroid(const PrimRef& p) { return p.min + p.max; }

Aabb primBox(const PrimRef& p) { return Aabb{p.min, p.max}; }

struct Task {
  uint32_t begin;
  uint32_t end;
  uint32_t depth;  // inner nodes above this one
  uint32_t slot;   // parent node * 2 + side, or kRootSlot
  Aabb bounds;
  Aabb centroids;  // of doubled centroids
};

struct Split {
  int axis = -1;
  uint32_t bin = 0;  // prims with bin index < bin go left
  float cost = std::numeric_limits<float>::infinity();
  float scale = 0.0f;
  Aabb left;
  Aabb right;
  uint32_t leftCount = 0;
};

// Maps a doubled centroid coordinate to its bin; the same expression is used
// for binning and partitioning, so both agree exactly.
uint32_t binOf(float c, float lo, float scale, uint32_t binCount) {
  float f = (c - lo) * scale;
  return std::min(static_cast<uint32_t>(f), binCount - 1);
}

Split findSahSplit(const std::vector<PrimRef>& prims, const Task& task, uint32_t binCount) {
  Split best;
  glm::vec3 extent = task.centroids.extent();
  std::array<float, 3> scale{};
  bool anyAxis = false;
  for (int a = 0; a < 3; ++a) {
    scale[a] = extent[a] > 0.0f ? static_cast<float>(binCount) / extent[a] : 0.0f;
    if (!std::isfinite(scale[a])) scale[a] = 0.0f;  // denormal extent: not splittable
    anyAxis = anyAxis || scale[a] > 0.0f;
  }
  if (!anyAxis) return best;

  // Bins without default member initializers: only the bins in use are reset
  // (this runs once per node, and most nodes are small).
  struct Bin {
    glm::vec3 min;
    glm::vec3 max;
    uint32_t count;
  };
  Bin bins[3][kMaxBins];
  for (int a = 0; a < 3; ++a) {
    for (uint32_t b = 0; b < binCount; ++b) bins[a][b] = {Aabb{}.min, Aabb{}.max, 0};
  }
  for (uint32_t i = task.begin; i < task.end; ++i) {
    const PrimRef& p = prims[i];
    glm::vec3 c = doubledCentroid(p);
    for (int a = 0; a < 3; ++a) {
      if (scale[a] == 0.0f) continue;
      Bin& bin = bins[a][binOf(c[a], task.centroids.min[a], scale[a], binCount)];
      bin.count++;
      bin.min = glm::min(bin.min, p.min);
      bin.max = glm::max(bin.max, p.max);
    }
  }

  std::array<float, kMaxBins> rightCost{};
  const uint32_t count = task.end - task.begin;
  for (int a = 0; a < 3; ++a) {
    if (scale[a] == 0.0f) continue;
    Aabb right;
    uint32_t rightCount = 0;
    float cost = 0.0f;
    for (uint32_t b = binCount - 1; b > 0; --b) {
      if (bins[a][b].count > 0) {  // an empty bin changes nothing (small nodes: most bins)
        right.grow(Aabb{bins[a][b].min, bins[a][b].max});
        rightCount += bins[a][b].count;
        cost = right.halfArea() * static_cast<float>(rightCount);
      }
      rightCost[b] = cost;
    }
    Aabb left;
    uint32_t leftCount = 0;
    for (uint32_t b = 1; b < binCount; ++b) {
      // After an empty bin the split equals the previous one: nothing to evaluate.
      if (bins[a][b - 1].count == 0) continue;
      left.grow(Aabb{bins[a][b - 1].min, bins[a][b - 1].max});
      leftCount += bins[a][b - 1].count;
      if (leftCount == count) continue;
      float splitCost = left.halfArea() * static_cast<float>(leftCount) + rightCost[b];
      if (splitCost < best.cost) {
        best.axis = a;
        best.bin = b;
        best.cost = splitCost;
        best.scale = scale[a];
        best.left = left;
        best.leftCount = leftCount;
      }
    }
  }
  if (best.axis >= 0) {
    for (uint32_t b = best.bin; b < binCount; ++b) {
      best.right.grow(Aabb{bins[best.axis][b].min, bins[best.axis][b].max});
    }
  }
  return best;
}

// Two-pointer partition that also collects each side's centroid bounds, so
// the children need no extra pass for them.
template <typename GoesLeft>
uint32_t partitionRange(std::vector<PrimRef>& prims, uint32_t begin, uint32_t end,
                        GoesLeft goesLeft, Aabb& leftCentroids, Aabb& rightCentroids) {
  uint32_t i = begin;
  uint32_t j = end;
  while (true) {
    while (i < j && goesLeft(prims[i])) leftCentroids.grow(doubledCentroid(prims[i++]));
    while (i < j && !goesLeft(prims[j - 1])) rightCentroids.grow(doubledCentroid(prims[--j]));
    if (i >= j) return i;
    std::swap(prims[i], prims[j - 1]);
  }
}

Aabb boundsOf(const std::vector<PrimRef>& prims, uint32_t begin, uint32_t end, Aabb& centroids) {
  Aabb box;
  for (uint32_t i = begin; i < end; ++i) {
    box.grow(primBox(prims[i]));
    centroids.grow(doubledCentroid(prims[i]));
  }
  return box;
}

}  // namespace

uint32_t levelsNeeded(uint32_t count, uint32_t maxLeafSize) {
  uint64_t leaves = (uint64_t{count} + maxLeafSize - 1) / maxLeafSize;
  uint32_t levels = 0;
  while ((uint64_t{1} << levels) < leaves) ++levels;
  return levels;
}

namespace {

// Sets a parent's child ref (or the root ref) once the child is known.
void link(BuiltTree& tree, uint32_t slot, uint32_t ref) {
  if (slot == kRootSlot) {
    tree.rootRef = ref;
  } else {
    tree.nodes[slot >> 1].child[slot & 1] = ref;
  }
}

// Builds every task on the stack into `tree`. Tasks of at least deferCount
// prims, when deferred is given, are split no further but handed back (the
// parallel phase builds them as separate trees).
void runTasks(std::vector<PrimRef>& prims, const BuildOptions& options, BuiltTree& tree,
              std::vector<Task> stack, uint32_t deferCount, std::vector<Task>* deferred) {
  while (!stack.empty()) {
    Task task = stack.back();
    stack.pop_back();
    const uint32_t count = task.end - task.begin;
    if (deferred && count < deferCount) {
      deferred->push_back(task);
      continue;
    }
    const uint32_t budget = options.maxDepth - task.depth;  // >= levelsNeeded(count)

    Split split;
    if (count > 1 && budget > 0) split = findSahSplit(prims, task, options.binCount);
    if (count <= options.maxLeafSize) {
      float area = task.bounds.halfArea();
      float leafCost = area * static_cast<float>(count);
      float splitCost = options.traversalCost * area + split.cost;
      if (split.axis < 0 || !(splitCost < leafCost)) {
        link(tree, task.slot, kBvhLeafBit | task.begin << kBvhLeafCountBits | (count - 1));
        tree.depth = std::max(tree.depth, task.depth);
        continue;
      }
    }

    bool sahFits = split.axis >= 0 && levelsNeeded(split.leftCount, options.maxLeafSize) < budget &&
                   levelsNeeded(count - split.leftCount, options.maxLeafSize) < budget;
    Task left{task.begin, 0, task.depth + 1, 0, {}, {}};
    Task right{0, task.end, task.depth + 1, 0, {}, {}};
    if (sahFits) {
      int axis = split.axis;
      float lo = task.centroids.min[axis];
      uint32_t mid = partitionRange(
          prims, task.begin, task.end,
          [&](const PrimRef& p) {
            return binOf(doubledCentroid(p)[axis], lo, split.scale, options.binCount) < split.bin;
          },
          left.centroids, right.centroids);
      left.end = right.begin = mid;
      left.bounds = split.left;
      right.bounds = split.right;
    } else {
      // Object median along the widest centroid axis: balanced, so the
      // children need one level fewer than this node.
      glm::vec3 e = task.centroids.extent();
      int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
      uint32_t mid = task.begin + count / 2;
      std::nth_element(prims.begin() + task.begin, prims.begin() + mid, prims.begin() + task.end,
                       [axis](const PrimRef& a, const PrimRef& b) {
                         return doubledCentroid(a)[axis] < doubledCentroid(b)[axis];
                       });
      left.end = right.begin = mid;
      left.bounds = boundsOf(prims, left.begin, left.end, left.centroids);
      right.bounds = boundsOf(prims, right.begin, right.end, right.centroids);
    }

    uint32_t node = static_cast<uint32_t>(tree.nodes.size());
    tree.nodes.push_back(BuildNode{{left.bounds, right.bounds}, {0, 0}});
    link(tree, task.slot, node);
    left.slot = node * 2;
    right.slot = node * 2 + 1;
    stack.push_back(right);  // left on top: depth-first, left subtree right after its parent
    stack.push_back(left);
  }
}

}  // namespace

BuiltTree buildSah(std::vector<PrimRef>& prims, const BuildOptions& options) {
  if (prims.empty()) throw std::runtime_error("engine/bvh/sah_builder.cpp: no primitives to build");
  if (prims.size() > shared::kBvhMaxTriangles) {
    throw std::runtime_error("engine/bvh/sah_builder.cpp: " + std::to_string(prims.size()) +
                             " primitives exceed the 2^28 the node layout can address");
  }
  if (options.binCount < 2 || options.binCount > kMaxBins || options.maxLeafSize < 1 ||
      options.maxLeafSize > shared::kBvhMaxLeafTriangles) {
    throw std::runtime_error("engine/bvh/sah_builder.cpp: bin count or leaf size out of range");
  }
  const uint32_t total = static_cast<uint32_t>(prims.size());
  if (levelsNeeded(total, options.maxLeafSize) > options.maxDepth) {
    throw std::runtime_error("engine/bvh/sah_builder.cpp: " + std::to_string(total) +
                             " primitives do not fit in a tree of depth " +
                             std::to_string(options.maxDepth));
  }

  BuiltTree tree;
  tree.nodes.reserve(2 * total / options.maxLeafSize + 1);
  Task root{0, total, 0, kRootSlot, {}, {}};
  root.bounds = boundsOf(prims, 0, total, root.centroids);
  tree.bounds = root.bounds;

  const uint32_t threads =
      std::max(1u, std::min(options.threads, std::thread::hardware_concurrency()));
  if (threads == 1 || total < kParallelBuildMinPrims) {
    runTasks(prims, options, tree, {root}, 0, nullptr);
    return tree;
  }

  // Parallel: split the top sequentially into subtrees of under total/8
  // prims, build those on worker threads (disjoint prim ranges), then append
  // their nodes in order. The result is the same tree as a sequential build,
  // with the nodes in a different order.
  std::vector<Task> deferred;
  runTasks(prims, options, tree, {root}, std::max(total / 8, 1u), &deferred);
  std::vector<BuiltTree> subtrees(deferred.size());
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < deferred.size(); i = next++) {
      Task task = deferred[i];
      task.slot = kRootSlot;
      runTasks(prims, options, subtrees[i], {task}, 0, nullptr);
    }
  };
  std::vector<std::thread> pool;
  for (uint32_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();

  for (size_t i = 0; i < deferred.size(); ++i) {
    const BuiltTree& sub = subtrees[i];
    const uint32_t offset = static_cast<uint32_t>(tree.nodes.size());
    auto rebase = [offset](uint32_t ref) { return (ref & kBvhLeafBit) ? ref : ref + offset; };
    for (const BuildNode& n : sub.nodes) {
      tree.nodes.push_back(
          BuildNode{{n.box[0], n.box[1]}, {rebase(n.child[0]), rebase(n.child[1])}});
    }
    link(tree, deferred[i].slot, rebase(sub.rootRef));
    tree.depth = std::max(tree.depth, sub.depth);  // task depths were absolute already
  }
  return tree;
}

}  // namespace qlight::bvh
