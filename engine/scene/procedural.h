// Building blocks for scenes made in code (tools/gen_scenes, tests): quads and boxes appended
// to a MeshAsset, nodes appended to a SceneAsset with the hierarchy kept consistent.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/scene/scene_asset.h"

namespace qlight::scene {

// A planar quad p0 p1 p2 p3, counter-clockwise seen from its front (the side it emits from
// when emissive), as two triangles with the face normal and uv (0,0) (1,0) (1,1) (0,1).
void addQuad(MeshAsset& mesh, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
             uint32_t material);

// Faces of a box, for leaving out the ones nobody can see.
enum BoxFace : uint32_t {
  kBoxMinX = 1,
  kBoxMaxX = 2,
  kBoxMinY = 4,
  kBoxMaxY = 8,
  kBoxMinZ = 16,
  kBoxMaxZ = 32,
  kBoxAllFaces = 63
};

// The box [-halfExtents, halfExtents] placed by worldFromBox, faces pointing outward (a solid
// block) or inward (a room seen from inside).
void addBox(MeshAsset& mesh, const glm::mat4& worldFromBox, glm::vec3 halfExtents,
            uint32_t material, bool facingInward = false, uint32_t faces = kBoxAllFaces);

// Appends a node (as a root, or as the last child of parent) and returns its index.
uint32_t addNode(SceneAsset& scene, NodeAsset node, int32_t parent = -1);

// The mesh appended to the scene and placed by a root node at the origin; returns the node.
uint32_t addMeshAtOrigin(SceneAsset& scene, MeshAsset mesh);
// A perspective camera (vertical field of view yfov) at `position`, turned by `rotation`
// (glTF cameras look down -z); returns its node.
uint32_t addCameraNode(SceneAsset& scene, float yfov, glm::vec3 position,
                       glm::quat rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
// A KHR_lights_punctual point light of `intensity` candela at `position`; returns its node.
uint32_t addPointLightNode(SceneAsset& scene, float intensity, glm::vec3 position);

// Recomputes every mesh's object-space bounds and the scene's world bounds at t = 0.
void refreshBounds(SceneAsset& scene);

}  // namespace qlight::scene
