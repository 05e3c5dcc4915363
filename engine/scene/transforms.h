// Node transforms: TRS <-> matrix, and world transforms of a SceneAsset's hierarchy.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "engine/scene/scene_asset.h"

namespace qlight::scene {

// parentFromLocal = T * R * S.
glm::mat4 toMatrix(const LocalTransform& local);

// Splits an affine matrix into T, R, S (a negative determinant goes into scale.x; shear, which
// TRS cannot hold, is dropped). toMatrix(decompose(m)) == m for every TRS matrix.
LocalTransform decompose(const glm::mat4& parentFromLocal);

// Every node's own TRS, as in the file.
std::vector<LocalTransform> restPose(const SceneAsset& scene);

// Nodes ordered parents before children: the shown scene's nodes only (from rootNodes), or
// all nodes when allNodes is set.
std::vector<uint32_t> nodesParentFirst(const SceneAsset& scene, bool allNodes = false);

// worldFromLocal of every node (identity for nodes outside the shown scene), given each
// node's local transform (restPose() or animate()).
std::vector<glm::mat4> worldTransforms(const SceneAsset& scene,
                                       const std::vector<LocalTransform>& locals);

// World-space bounds of the shown scene's mesh instances (every vertex transformed).
Bounds worldBounds(const SceneAsset& scene, const std::vector<glm::mat4>& worldFromNode);

}  // namespace qlight::scene
