// The scene's two-level BVH as texel arrays ready for upload: BLASes built once
// per mesh, the TLAS rebuilt when instances move.
#pragma once
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "engine/render/scene_draw.h"
#include "engine/scene/scene_asset.h"

namespace qlight::render {

class SceneAccel {
 public:
  SceneAccel();
  ~SceneAccel();
  SceneAccel(SceneAccel&&) noexcept;
  SceneAccel& operator=(SceneAccel&&) noexcept;

  void buildMeshes(const std::vector<scene::MeshAsset>& meshes);
  // The most triangles the merged BLAS of fixed instances may copy (SceneBvh).
  void setMaxMergedTriangles(uint32_t count);
  // A deformed mesh's new positions (same indices): its BLAS is refitted.
  void refitMesh(uint32_t mesh, std::span<const glm::vec3> positions,
                 std::span<const uint32_t> indices);
  void buildInstances(const std::vector<MeshDraw>& draws);

  // Grows whenever triangleTexels() changes (a refit, the merged static geometry rebuilt).
  uint64_t trianglesVersion() const;
  const std::vector<glm::vec4>& nodeTexels() const;
  const std::vector<glm::vec4>& triangleTexels() const;
  const std::vector<glm::vec4>& instanceTexels() const;

  // The distance to the nearest surface along a ray, traced on the CPU by the shaders'
  // own traversal (the window's picking: a few rays a second).
  std::optional<float> closestHit(glm::vec3 origin, glm::vec3 direction) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace qlight::render
