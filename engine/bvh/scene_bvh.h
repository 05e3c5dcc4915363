// Two-level BVH of a scene: one bottom level (BLAS) per mesh, built once, and
// a top level (TLAS) over instances, rebuilt alone whenever instances move
// (animated rigid nodes), in time O(n log n) in the instance count.
//
// Usage: addMesh() per mesh, then rebuildTopLevel(instances) each time the
// instance list or a transform changes (after refitMesh() for deformed meshes); upload flat().
// After a top-level rebuild only the header node, the node tail from topLevelNodeOffset() and the
// instance array change. addMesh() empties the top level until the next rebuildTopLevel().
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "engine/bvh/aabb.h"
#include "engine/bvh/flat_bvh.h"
#include "engine/bvh/sah_builder.h"

namespace qlight::bvh {

struct Instance {
  glm::mat4 worldFromObject{1.0f};
  uint32_t blas = 0;         // index returned by addMesh
  uint32_t customIndex = 0;  // the renderer's own id, stored in the instance texels
  // Never moves and its mesh is never deformed: its triangles may join the merged BLAS.
  bool fixed = false;
};

// The merged BLAS: the fixed instances' triangles in world space, in one tree.
struct MergedInfo {
  uint32_t rootRef = 0;  // 0 when no instance is merged
  uint32_t nodeCount = 0;
  uint32_t triangleCount = 0;
  uint32_t instances = 0;  // how many instances it holds
  uint64_t builds = 0;     // how many times it was built (it is kept while its set stays)
};

struct BlasInfo {
  uint32_t rootRef = 0;  // global ref (node index or leaf); 0 when the mesh has no triangle
  uint32_t nodeOffset = 0;
  uint32_t nodeCount = 0;
  uint32_t triangleOffset = 0;  // first texel triangle (index into flat().triangleIndices)
  uint32_t triangleCount = 0;   // triangles kept (degenerate ones are dropped)
  uint32_t meshTriangleCount = 0;
  uint32_t depth = 0;
  Aabb bounds;           // object space, padded like the node boxes
  Aabb rootChildren[2];  // the root's child boxes (both = bounds for a leaf root)
};

struct TopLevelInfo {
  uint32_t rootRef = 0;  // 0 when no instance can be hit
  uint32_t nodeOffset = 0;
  uint32_t nodeCount = 0;
  uint32_t depth = 0;
  uint32_t hittableInstances = 0;
  Aabb bounds;  // world space, of the hittable instances
};

// Zero-area triangles (a vertex repeated, or collinear so the float cross
// product is exactly zero) can never be hit and have no normal: the BLAS
// leaves them out.
bool isDegenerateTriangle(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2);

struct MeshTree;  // a mesh's built tree before it joins the arrays (scene_bvh.cpp)

// One mesh for addMeshes.
struct MeshInput {
  std::span<const glm::vec3> positions;
  std::span<const uint32_t> indices;
};

class SceneBvh {
 public:
  SceneBvh();

  // Builds the bottom level of one mesh and returns its index. positions in
  // object space, indices are triplets. Throws std::runtime_error on an index
  // out of range, a non-finite position or a count not divisible by 3.
  uint32_t addMesh(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                   const BuildOptions& options = {});

  // addMesh for each mesh in order (BLAS i is meshes[i]), the trees built on
  // options.threads threads: small meshes one per thread, large ones (whose
  // build is parallel itself) one after the other. Same result as addMesh.
  void addMeshes(std::span<const MeshInput> meshes, const BuildOptions& options = {});

  // Moves a BLAS's vertices (a skinned or morphed mesh: same indices, new positions) and
  // refits its node boxes bottom-up; its layout (nodes, triangle order) stays, so nothing
  // else moves. Triangles left out as degenerate when it was built stay out. Call
  // rebuildTopLevel afterwards: the instances' boxes changed. Throws on a position count
  // that does not match the indices, or a non-finite position.
  void refitMesh(uint32_t blas, std::span<const glm::vec3> positions,
                 std::span<const uint32_t> indices);

  // Rebuilds the top level and the instance array; BLASes stay untouched.
  // Instances with a singular or non-finite transform, or an empty mesh, get
  // their texels but cannot be hit. Throws on a bad blas index.
  // Fixed instances (see Instance::fixed) go into the merged BLAS, which is built
  // again only when the set of fixed instances, their transforms or their meshes
  // change; hits in it report the instance a triangle came from, so callers see
  // the same instance and primitive either way. The copy holds at most
  // maxMergedTriangles: instances of meshes used once go first, then those of
  // meshes that several fixed instances share (their copies cost memory where
  // the instancing saved it); the rest stay instances of their BLAS.
  void rebuildTopLevel(std::span<const Instance> instances);

  static constexpr uint32_t kDefaultMaxMergedTriangles = 1u << 21;
  // Takes effect at the next rebuildTopLevel.
  void setMaxMergedTriangles(uint32_t count) { maxMergedTriangles_ = count; }

  const FlatBvh& flat() const { return flat_; }
  const BlasInfo& blas(uint32_t index) const { return blases_.at(index); }
  uint32_t blasCount() const { return static_cast<uint32_t>(blases_.size()); }
  const TopLevelInfo& topLevel() const { return topLevel_; }
  const MergedInfo& merged() const { return merged_; }
  // First node of the top level; nodes before it are the header, the BLASes and the merged BLAS.
  uint32_t topLevelNodeOffset() const { return mergedNodeEnd_; }
  // Grows whenever flat().triangles changes (a mesh added or refitted, the merged BLAS rebuilt).
  uint64_t trianglesVersion() const { return trianglesVersion_; }

 private:
  // What the merged BLAS was built from; built again when this changes.
  struct MergedEntry {
    uint32_t instance;
    uint32_t blas;
    uint64_t blasVersion;
    glm::mat4 worldFromObject;
    bool operator==(const MergedEntry&) const = default;
  };

  uint32_t appendMesh(MeshTree built, std::span<const glm::vec3> positions,
                      std::span<const uint32_t> indices);
  std::vector<MergedEntry> chooseMerged(std::span<const Instance> instances,
                                        const std::vector<bool>& hittable) const;
  void buildMerged(std::vector<MergedEntry> entries);
  void dropMerged();
  void writeHeader();

  FlatBvh flat_;
  std::vector<BlasInfo> blases_;
  std::vector<uint64_t> blasVersions_;  // grows with each refit
  TopLevelInfo topLevel_;
  MergedInfo merged_;
  std::vector<MergedEntry> mergedFrom_;
  Aabb mergedRootChildren_[2];
  uint32_t blasNodeEnd_ = 1;  // node 0 is the header
  uint32_t mergedNodeEnd_ = 1;
  uint32_t blasTriangleEnd_ = 0;
  uint32_t instanceCount_ = 0;
  uint64_t trianglesVersion_ = 0;
  uint32_t maxMergedTriangles_ = kDefaultMaxMergedTriangles;
};

}  // namespace qlight::bvh
