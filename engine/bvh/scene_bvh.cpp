#include "engine/bvh/scene_bvh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

namespace qlight::bvh {
namespace {

using shared::kBvhInstanceTexels;
using shared::kBvhLeafBit;
using shared::kBvhLeafCountBits;
using shared::kBvhNodeTexels;

// Instance boxes grow by this fraction of their largest coordinate, so a ray
// that reaches a triangle in object space (after its own rounding in the
// transform) never misses the world-space box.
constexpr double kInstanceBoxPad = 1.0 / (1 << 17);

// Node boxes grow a little before they are written: the watertight test's t
// is less exact than the slab test's (it is assembled from vertex offsets to
// the origin, so its error scales with the triangle's size and coordinates),
// and a box must never be culled by a hit distance that is off by that error.
constexpr float kNodeBoxPadExtent = 1.0f / (1 << 17);
constexpr float kNodeBoxPadMagnitude = 1.0f / (1 << 20);

float bits(uint32_t u) { return std::bit_cast<float>(u); }

Aabb padded(const Aabb& b) {
  glm::vec3 e = b.extent();
  glm::vec3 m = glm::max(glm::abs(b.min), glm::abs(b.max));
  float pad = kNodeBoxPadExtent * std::max(e.x, std::max(e.y, e.z)) +
              kNodeBoxPadMagnitude * std::max(m.x, std::max(m.y, m.z));
  return Aabb{b.min - pad, b.max + pad};
}

glm::vec4 point(const glm::vec3& p, uint32_t w) { return glm::vec4(p, bits(w)); }

bool finite(const glm::vec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Refs of a built tree rebased into the concatenated arrays.
uint32_t globalRef(uint32_t local, uint32_t nodeOffset, uint32_t triangleOffset) {
  if (local & kBvhLeafBit) return local + (triangleOffset << kBvhLeafCountBits);
  return local + nodeOffset;
}

void appendNodes(std::vector<glm::vec4>& out, const BuiltTree& tree, auto&& rebase) {
  for (const BuildNode& n : tree.nodes) {
    Aabb left = padded(n.box[0]), right = padded(n.box[1]);
    out.push_back(point(left.min, rebase(n.child[0])));
    out.push_back(point(left.max, 0));
    out.push_back(point(right.min, rebase(n.child[1])));
    out.push_back(point(right.max, 0));
  }
}

Aabb transformBox(const glm::dmat4& m, const Aabb& box) {
  glm::dvec3 lo(std::numeric_limits<double>::max());
  glm::dvec3 hi(-std::numeric_limits<double>::max());
  for (int corner = 0; corner < 8; ++corner) {
    glm::dvec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                 (corner & 4) ? box.max.z : box.min.z);
    glm::dvec3 q = glm::dvec3(m * glm::dvec4(p, 1.0));
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  glm::dvec3 m3 = glm::max(glm::abs(lo), glm::abs(hi));
  double magnitude = std::max(m3.x, std::max(m3.y, m3.z));
  double pad = magnitude * kInstanceBoxPad + 1e-30;
  return Aabb{glm::vec3(lo - pad), glm::vec3(hi + pad)};
}

// One instance's 8 texels (layout: bvh_types.h).
void writeInstanceTexels(glm::vec4* texels, const glm::mat4& worldFromObject,
                         const glm::mat4& objectFromWorld, uint32_t rootRef,
                         uint32_t triangleOffset, uint32_t customIndex, uint32_t blas) {
  for (int r = 0; r < 3; ++r) {  // glm is column-major: m[column][row]
    const glm::mat4& inv = objectFromWorld;
    const glm::mat4& m = worldFromObject;
    texels[shared::kBvhInstanceObjectFromWorld + r] =
        glm::vec4(inv[0][r], inv[1][r], inv[2][r], inv[3][r]);
    texels[shared::kBvhInstanceWorldFromObject + r] = glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
  }
  texels[shared::kBvhInstanceInfo] =
      glm::vec4(bits(rootRef), bits(triangleOffset), bits(customIndex), bits(blas));
}

}  // namespace

bool isDegenerateTriangle(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
  return n.x == 0.0f && n.y == 0.0f && n.z == 0.0f;
}

SceneBvh::SceneBvh() { writeHeader(); }

// One mesh's tree, built on its own (any thread) before it joins the concatenated arrays.
struct MeshTree {
  std::vector<PrimRef> prims;  // leaf order after the build
  BuiltTree tree;
  uint32_t meshTriangles = 0;
};

namespace {

MeshTree buildMeshTree(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                       const BuildOptions& options) {
  if (indices.size() % 3 != 0) {
    throw std::runtime_error("engine/bvh/scene_bvh.cpp: index count " +
                             std::to_string(indices.size()) + " is not a multiple of 3");
  }
  MeshTree out;
  out.meshTriangles = static_cast<uint32_t>(indices.size() / 3);
  std::vector<PrimRef>& prims = out.prims;
  prims.reserve(out.meshTriangles);
  for (uint32_t t = 0; t < out.meshTriangles; ++t) {
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) {
      uint32_t index = indices[3 * t + k];
      if (index >= positions.size()) {
        throw std::runtime_error("engine/bvh/scene_bvh.cpp: index " + std::to_string(index) +
                                 " out of range of " + std::to_string(positions.size()) +
                                 " positions");
      }
      p[k] = positions[index];
      if (!finite(p[k])) {
        throw std::runtime_error("engine/bvh/scene_bvh.cpp: non-finite vertex position " +
                                 std::to_string(index));
      }
    }
    if (isDegenerateTriangle(p[0], p[1], p[2])) continue;
    prims.push_back(
        PrimRef{glm::min(p[0], glm::min(p[1], p[2])), t, glm::max(p[0], glm::max(p[1], p[2]))});
  }
  if (!prims.empty()) out.tree = buildSah(prims, options);
  return out;
}

}  // namespace

uint32_t SceneBvh::addMesh(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                           const BuildOptions& options) {
  return appendMesh(buildMeshTree(positions, indices, options), positions, indices);
}

void SceneBvh::addMeshes(std::span<const MeshInput> meshes, const BuildOptions& options) {
  // Small meshes build one per thread; a large one (whose build is parallel itself) alone.
  const uint32_t threads =
      std::max(1u, std::min(options.threads, std::thread::hardware_concurrency()));
  std::vector<MeshTree> trees(meshes.size());
  std::vector<std::exception_ptr> errors(meshes.size());
  BuildOptions single = options;
  single.threads = 1;
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < meshes.size(); i = next++) {
      if (meshes[i].indices.size() / 3 >= kParallelBuildMinPrims) continue;
      try {
        trees[i] = buildMeshTree(meshes[i].positions, meshes[i].indices, single);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (uint32_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  for (size_t i = 0; i < meshes.size(); ++i) {
    if (errors[i]) std::rethrow_exception(errors[i]);
    if (meshes[i].indices.size() / 3 >= kParallelBuildMinPrims)
      trees[i] = buildMeshTree(meshes[i].positions, meshes[i].indices, options);
    appendMesh(std::move(trees[i]), meshes[i].positions, meshes[i].indices);
  }
}

uint32_t SceneBvh::appendMesh(MeshTree built, std::span<const glm::vec3> positions,
                              std::span<const uint32_t> indices) {
  dropMerged();  // mesh triangles come first; the merged ones are copied after them
  const std::vector<PrimRef>& prims = built.prims;
  const BuiltTree& tree = built.tree;
  BlasInfo info;
  info.meshTriangleCount = built.meshTriangles;
  info.triangleOffset = static_cast<uint32_t>(flat_.triangleIndices.size());
  info.nodeOffset = blasNodeEnd_;
  if (uint64_t{info.triangleOffset} + prims.size() > shared::kBvhMaxTriangles) {
    throw std::runtime_error("engine/bvh/scene_bvh.cpp: more than 2^28 triangles in all meshes");
  }

  flat_.nodes.resize(std::size_t{blasNodeEnd_} * kBvhNodeTexels);  // the top level goes stale
  if (!prims.empty()) {
    auto rebase = [&](uint32_t ref) {
      return globalRef(ref, info.nodeOffset, info.triangleOffset);
    };
    appendNodes(flat_.nodes, tree, rebase);
    for (const PrimRef& prim : prims) {
      const uint32_t* tri = &indices[3 * prim.index];
      flat_.triangles.push_back(point(positions[tri[0]], prim.index));
      flat_.triangles.push_back(point(positions[tri[1]], 0));
      flat_.triangles.push_back(point(positions[tri[2]], 0));
      flat_.triangleIndices.push_back(prim.index);
    }
    info.rootRef = rebase(tree.rootRef);
    info.nodeCount = static_cast<uint32_t>(tree.nodes.size());
    info.triangleCount = static_cast<uint32_t>(prims.size());
    info.depth = tree.depth;
    info.bounds = padded(tree.bounds);
    bool innerRoot = !(tree.rootRef & kBvhLeafBit);
    info.rootChildren[0] = innerRoot ? padded(tree.nodes[0].box[0]) : info.bounds;
    info.rootChildren[1] = innerRoot ? padded(tree.nodes[0].box[1]) : info.bounds;
    blasNodeEnd_ += info.nodeCount;
  }
  blases_.push_back(info);
  blasVersions_.push_back(0);
  blasTriangleEnd_ = static_cast<uint32_t>(flat_.triangleIndices.size());
  mergedNodeEnd_ = blasNodeEnd_;
  ++trianglesVersion_;
  topLevel_ = TopLevelInfo{};
  topLevel_.nodeOffset = mergedNodeEnd_;
  writeHeader();
  return static_cast<uint32_t>(blases_.size() - 1);
}

void SceneBvh::refitMesh(uint32_t index, std::span<const glm::vec3> positions,
                         std::span<const uint32_t> indices) {
  BlasInfo& info = blases_.at(index);
  if (indices.size() != std::size_t{info.meshTriangleCount} * 3)
    throw std::runtime_error(
        "engine/bvh/scene_bvh.cpp: refit with " + std::to_string(indices.size() / 3) +
        " triangles of a mesh built with " + std::to_string(info.meshTriangleCount));
  if (info.rootRef == 0) return;
  ++blasVersions_[index];  // merged copies of it go stale: the next top-level rebuild redoes them
  ++trianglesVersion_;
  for (uint32_t k = info.triangleOffset; k < info.triangleOffset + info.triangleCount; ++k) {
    const uint32_t* tri = &indices[3 * std::size_t{flat_.triangleIndices[k]}];
    for (int c = 0; c < 3; ++c) {
      if (tri[c] >= positions.size() || !finite(positions[tri[c]]))
        throw std::runtime_error("engine/bvh/scene_bvh.cpp: refit vertex " +
                                 std::to_string(tri[c]) + " is missing or not finite");
      glm::vec4& texel = flat_.triangles[3 * std::size_t{k} + c];
      texel = glm::vec4(positions[tri[c]], texel.w);  // w: the triangle's index, kept
    }
  }
  // Children come after their parents in a built tree, so one backward pass sees every
  // child before its parent. Boxes are kept unpadded here and padded once when written.
  auto leafBox = [&](uint32_t ref) {
    Aabb box;
    const uint32_t first = shared::bvhLeafFirst(ref);
    for (uint32_t t = first; t < first + shared::bvhLeafCount(ref); ++t)
      for (int c = 0; c < 3; ++c) box.grow(glm::vec3(flat_.triangles[3 * std::size_t{t} + c]));
    return box;
  };
  std::vector<Aabb> boxes(info.nodeCount);
  std::vector<std::array<Aabb, 2>> children(info.nodeCount);
  for (uint32_t i = info.nodeCount; i-- > 0;) {
    const std::size_t texel = std::size_t{info.nodeOffset + i} * kBvhNodeTexels;
    for (int side = 0; side < 2; ++side) {
      const uint32_t ref = std::bit_cast<uint32_t>(flat_.nodes[texel + 2 * side].w);
      children[i][side] = (ref & kBvhLeafBit) ? leafBox(ref) : boxes.at(ref - info.nodeOffset);
      const Aabb p = padded(children[i][side]);
      flat_.nodes[texel + 2 * side] = point(p.min, ref);
      flat_.nodes[texel + 2 * side + 1] = point(p.max, 0);
    }
    boxes[i] = unite(children[i][0], children[i][1]);
  }
  const bool innerRoot = !(info.rootRef & kBvhLeafBit);
  const Aabb bounds = innerRoot ? boxes[0] : leafBox(info.rootRef);
  info.bounds = padded(bounds);
  info.rootChildren[0] = innerRoot ? padded(children[0][0]) : info.bounds;
  info.rootChildren[1] = innerRoot ? padded(children[0][1]) : info.bounds;
}

void SceneBvh::rebuildTopLevel(std::span<const Instance> instances) {
  instanceCount_ = static_cast<uint32_t>(instances.size());
  std::vector<bool> hittable(instances.size(), false);
  std::vector<Aabb> worldBoxes(instances.size());
  std::vector<glm::vec4> texels(instances.size() * kBvhInstanceTexels, glm::vec4(0.0f));
  for (uint32_t i = 0; i < instanceCount_; ++i) {
    const Instance& instance = instances[i];
    if (instance.blas >= blases_.size()) {
      throw std::runtime_error("engine/bvh/scene_bvh.cpp: instance " + std::to_string(i) +
                               " names blas " + std::to_string(instance.blas) + " of " +
                               std::to_string(blases_.size()));
    }
    const BlasInfo& blas = blases_[instance.blas];
    glm::dmat4 worldFromObject(instance.worldFromObject);
    glm::dmat4 objectFromWorld = glm::inverse(worldFromObject);
    bool invertible = std::isfinite(glm::determinant(worldFromObject)) &&
                      glm::determinant(worldFromObject) != 0.0;
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        invertible = invertible && std::isfinite(objectFromWorld[c][r]) &&
                     std::isfinite(worldFromObject[c][r]);
      }
    }
    hittable[i] = invertible && blas.rootRef != 0;

    glm::mat4 inverse = invertible ? glm::mat4(objectFromWorld) : glm::mat4(0.0f);
    writeInstanceTexels(&texels[std::size_t{i} * kBvhInstanceTexels], instance.worldFromObject,
                        inverse, hittable[i] ? blas.rootRef : 0, blas.triangleOffset,
                        instance.customIndex, instance.blas);
    if (hittable[i]) {
      worldBoxes[i] = transformBox(worldFromObject, blas.rootChildren[0]);
      worldBoxes[i].grow(transformBox(worldFromObject, blas.rootChildren[1]));
    }
  }

  std::vector<MergedEntry> merge = chooseMerged(instances, hittable);
  if (merge != mergedFrom_) buildMerged(std::move(merge));
  std::vector<bool> inMerged(instances.size(), false);
  for (const MergedEntry& e : mergedFrom_) inMerged[e.instance] = true;

  // The top level's leaves: the instances left out of the merged BLAS, and one identity
  // instance (after the caller's) that holds the merged BLAS.
  std::vector<PrimRef> prims;
  prims.reserve(instances.size() + 1);
  Aabb sceneBounds;
  for (uint32_t i = 0; i < instanceCount_; ++i) {
    if (!hittable[i]) continue;
    sceneBounds.grow(worldBoxes[i]);
    if (!inMerged[i]) prims.push_back(PrimRef{worldBoxes[i].min, i, worldBoxes[i].max});
  }
  if (merged_.rootRef != 0) {
    texels.resize(texels.size() + kBvhInstanceTexels, glm::vec4(0.0f));
    writeInstanceTexels(&texels[std::size_t{instanceCount_} * kBvhInstanceTexels], glm::mat4(1.0f),
                        glm::mat4(1.0f), merged_.rootRef, blasTriangleEnd_,
                        shared::kBvhInvalidIndex, shared::kBvhInvalidIndex);
    Aabb box = transformBox(glm::dmat4(1.0), mergedRootChildren_[0]);
    box.grow(transformBox(glm::dmat4(1.0), mergedRootChildren_[1]));
    prims.push_back(PrimRef{box.min, instanceCount_, box.max});
  }
  flat_.instances = std::move(texels);

  flat_.nodes.resize(std::size_t{mergedNodeEnd_} * kBvhNodeTexels);
  topLevel_ = TopLevelInfo{};
  topLevel_.nodeOffset = mergedNodeEnd_;
  topLevel_.hittableInstances =
      static_cast<uint32_t>(std::count(hittable.begin(), hittable.end(), true));
  if (!prims.empty()) {
    BuildOptions options;
    options.maxLeafSize = 1;
    options.maxDepth = shared::kBvhMaxTlasDepth;
    if (levelsNeeded(static_cast<uint32_t>(prims.size()), 1) > options.maxDepth) {
      throw std::runtime_error("engine/bvh/scene_bvh.cpp: " + std::to_string(prims.size()) +
                               " instances exceed the 2^18 the top level holds");
    }
    BuiltTree tree = buildSah(prims, options);  // reorders prims: leaf i holds prims[i]
    auto rebase = [&](uint32_t ref) {
      if (ref & kBvhLeafBit) return kBvhLeafBit | prims[shared::bvhLeafFirst(ref)].index;
      return ref + mergedNodeEnd_;
    };
    appendNodes(flat_.nodes, tree, rebase);
    topLevel_.rootRef = rebase(tree.rootRef);
    topLevel_.nodeCount = static_cast<uint32_t>(tree.nodes.size());
    topLevel_.depth = tree.depth;
    topLevel_.bounds = padded(sceneBounds);
  }
  writeHeader();
}

std::vector<SceneBvh::MergedEntry> SceneBvh::chooseMerged(std::span<const Instance> instances,
                                                          const std::vector<bool>& hittable) const {
  std::vector<uint32_t> uses(blases_.size(), 0);
  for (uint32_t i = 0; i < instances.size(); ++i)
    if (instances[i].fixed && hittable[i]) ++uses[instances[i].blas];
  std::vector<MergedEntry> out;
  uint64_t triangles = 0;
  for (int pass = 0; pass < 2; ++pass) {  // meshes used once first, then shared ones
    for (uint32_t i = 0; i < instances.size(); ++i) {
      const Instance& inst = instances[i];
      if (!inst.fixed || !hittable[i] || (uses[inst.blas] > 1) != (pass == 1)) continue;
      const uint32_t count = blases_[inst.blas].triangleCount;
      if (triangles + count > maxMergedTriangles_) continue;
      triangles += count;
      out.push_back({i, inst.blas, blasVersions_[inst.blas], inst.worldFromObject});
    }
  }
  std::sort(out.begin(), out.end(),
            [](const MergedEntry& a, const MergedEntry& b) { return a.instance < b.instance; });
  // One instance gains nothing from a copy of its own tree: leave it in the top level.
  if (out.size() < 2) out.clear();
  return out;
}

void SceneBvh::dropMerged() {
  flat_.triangles.resize(std::size_t{blasTriangleEnd_} * shared::kBvhTriangleTexels);
  flat_.triangleIndices.resize(blasTriangleEnd_);
  flat_.nodes.resize(std::size_t{blasNodeEnd_} * kBvhNodeTexels);
  if (merged_.rootRef != 0) ++trianglesVersion_;
  mergedNodeEnd_ = blasNodeEnd_;
  mergedFrom_.clear();
  const uint64_t builds = merged_.builds;
  merged_ = MergedInfo{};
  merged_.builds = builds;
}

void SceneBvh::buildMerged(std::vector<MergedEntry> entries) {
  dropMerged();
  mergedFrom_ = std::move(entries);
  if (mergedFrom_.empty()) return;
  // World-space copies of the instances' triangles. Each vertex is transformed on its own
  // (in double, rounded once), so triangles that share a vertex still share it exactly and
  // the watertight test keeps their common edges closed.
  std::vector<glm::vec4> world;  // 3 texels a triangle, in input order
  std::vector<PrimRef> prims;
  for (const MergedEntry& e : mergedFrom_) {
    const BlasInfo& blas = blases_[e.blas];
    const glm::dmat4 m(e.worldFromObject);
    for (uint32_t k = blas.triangleOffset; k < blas.triangleOffset + blas.triangleCount; ++k) {
      glm::vec3 p[3];
      for (int c = 0; c < 3; ++c) {
        const glm::vec3 q = glm::vec3(flat_.triangles[3 * std::size_t{k} + c]);
        p[c] = glm::vec3(m * glm::dvec4(q, 1.0));
      }
      if (isDegenerateTriangle(p[0], p[1], p[2]) || !finite(p[0]) || !finite(p[1]) || !finite(p[2]))
        continue;  // flattened by the transform's rounding: it cannot be hit
      prims.push_back(PrimRef{glm::min(p[0], glm::min(p[1], p[2])),
                              static_cast<uint32_t>(world.size() / 3),
                              glm::max(p[0], glm::max(p[1], p[2]))});
      world.push_back(point(p[0], flat_.triangleIndices[k]));
      world.push_back(point(p[1], e.instance + 1u));  // owner + 1
      world.push_back(point(p[2], 0));
    }
  }
  ++merged_.builds;
  merged_.instances = static_cast<uint32_t>(mergedFrom_.size());
  if (prims.empty()) return;
  if (uint64_t{blasTriangleEnd_} + prims.size() > shared::kBvhMaxTriangles) {
    throw std::runtime_error("engine/bvh/scene_bvh.cpp: more than 2^28 triangles in all meshes");
  }
  BuiltTree tree = buildSah(prims, BuildOptions{});
  auto rebase = [&](uint32_t ref) { return globalRef(ref, blasNodeEnd_, blasTriangleEnd_); };
  appendNodes(flat_.nodes, tree, rebase);
  for (const PrimRef& prim : prims) {
    for (int c = 0; c < 3; ++c) flat_.triangles.push_back(world[3 * std::size_t{prim.index} + c]);
    flat_.triangleIndices.push_back(std::bit_cast<uint32_t>(world[3 * std::size_t{prim.index}].w));
  }
  merged_.rootRef = rebase(tree.rootRef);
  merged_.nodeCount = static_cast<uint32_t>(tree.nodes.size());
  merged_.triangleCount = static_cast<uint32_t>(prims.size());
  const bool innerRoot = !(tree.rootRef & kBvhLeafBit);
  const Aabb bounds = padded(tree.bounds);
  mergedRootChildren_[0] = innerRoot ? padded(tree.nodes[0].box[0]) : bounds;
  mergedRootChildren_[1] = innerRoot ? padded(tree.nodes[0].box[1]) : bounds;
  mergedNodeEnd_ = blasNodeEnd_ + merged_.nodeCount;
  ++trianglesVersion_;
}

void SceneBvh::writeHeader() {
  if (flat_.nodes.size() < kBvhNodeTexels) flat_.nodes.resize(kBvhNodeTexels);
  const Aabb& b = topLevel_.bounds;
  bool hasBounds = !b.empty();
  flat_.nodes[0] = glm::vec4(bits(topLevel_.rootRef), bits(instanceCount_), bits(mergedNodeEnd_),
                             bits(static_cast<uint32_t>(flat_.nodes.size() / kBvhNodeTexels)));
  flat_.nodes[shared::kBvhHeaderSceneMin] =
      point(hasBounds ? b.min : glm::vec3(0.0f), static_cast<uint32_t>(blases_.size()));
  flat_.nodes[shared::kBvhHeaderSceneMax] = point(
      hasBounds ? b.max : glm::vec3(0.0f), static_cast<uint32_t>(flat_.triangleIndices.size()));
  flat_.nodes[3] = glm::vec4(0.0f);
}

}  // namespace qlight::bvh
