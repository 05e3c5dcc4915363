// Deforming a mesh's vertices (no ECS, no GPU): morph targets first, then the skin, then
// flat normals regenerated, as glTF orders them. Positions and normals travel together in
// DeformedVertices, so another per-vertex attribute (tangents) is one more array here.
#pragma once

#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "engine/scene/scene_asset.h"

namespace qlight::scene {

struct DeformedVertices {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // unit length
};

// worldFromJoint_i * inverseBind_i for each joint of `skin`, given every node's world transform.
std::vector<glm::mat4> jointMatrices(const SkinAsset& skin,
                                     const std::vector<glm::mat4>& worldFromNode);

// The mesh with its morph targets at `weights` (missing weights count as 0) and, when
// jointMatrices is not empty, skinned by them (the result is then in world space).
// Normals are renormalized; flat-shaded triangles get their new face normal.
DeformedVertices deformMesh(const MeshAsset& mesh, std::span<const float> weights,
                            std::span<const glm::mat4> jointMatrices);

// The morph weights a node starts from: its own, else its mesh's defaults.
std::vector<float> restWeights(const SceneAsset& scene, uint32_t node);

// Every node's morph weights at time t (restWeights with the Weights channels applied); empty
// for nodes whose mesh has no targets.
std::vector<std::vector<float>> animateWeights(const SceneAsset& scene, float timeSeconds,
                                               bool loop = false);

// World-space bounds of the shown scene at time t: rigid, instanced, morphed and skinned
// meshes as they are drawn then.
Bounds posedWorldBounds(const SceneAsset& scene, float timeSeconds);

}  // namespace qlight::scene
