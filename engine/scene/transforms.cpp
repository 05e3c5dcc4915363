#include "engine/scene/transforms.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace qlight::scene {

glm::mat4 toMatrix(const LocalTransform& local) {
  glm::mat4 m = glm::mat4_cast(local.rotation);
  m[0] *= local.scale.x;
  m[1] *= local.scale.y;
  m[2] *= local.scale.z;
  m[3] = glm::vec4(local.translation, 1.0f);
  return m;
}

LocalTransform decompose(const glm::mat4& m) {
  LocalTransform out;
  out.translation = glm::vec3(m[3]);
  glm::vec3 columns[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
  out.scale = {glm::length(columns[0]), glm::length(columns[1]), glm::length(columns[2])};
  if (glm::determinant(glm::mat3(m)) < 0.0f) out.scale.x = -out.scale.x;
  if (out.scale.x == 0.0f || out.scale.y == 0.0f || out.scale.z == 0.0f) return out;
  const glm::mat3 rotation(columns[0] / out.scale.x, columns[1] / out.scale.y,
                           columns[2] / out.scale.z);
  out.rotation = glm::normalize(glm::quat_cast(rotation));
  return out;
}

std::vector<LocalTransform> restPose(const SceneAsset& scene) {
  std::vector<LocalTransform> locals;
  locals.reserve(scene.nodes.size());
  for (const NodeAsset& node : scene.nodes) locals.push_back(node.local);
  return locals;
}

std::vector<uint32_t> nodesParentFirst(const SceneAsset& scene, bool allNodes) {
  std::vector<uint32_t> order;
  if (allNodes) {
    for (uint32_t i = 0; i < scene.nodes.size(); ++i)
      if (scene.nodes[i].parent < 0) order.push_back(i);
  } else {
    order = scene.rootNodes;
  }
  // Breadth first: the loader guarantees a forest, so this visits each node once.
  for (size_t next = 0; next < order.size(); ++next)
    for (uint32_t child : scene.nodes[order[next]].children) order.push_back(child);
  return order;
}

std::vector<glm::mat4> worldTransforms(const SceneAsset& scene,
                                       const std::vector<LocalTransform>& locals) {
  std::vector<glm::mat4> world(scene.nodes.size(), glm::mat4(1.0f));
  for (uint32_t i : nodesParentFirst(scene)) {
    const int32_t parent = scene.nodes[i].parent;
    const glm::mat4 parentFromLocal = toMatrix(locals[i]);
    world[i] = parent < 0 ? parentFromLocal : world[size_t(parent)] * parentFromLocal;
  }
  return world;
}

Bounds worldBounds(const SceneAsset& scene, const std::vector<glm::mat4>& worldFromNode) {
  Bounds bounds;
  for (uint32_t i : nodesParentFirst(scene)) {
    const int32_t mesh = scene.nodes[i].mesh;
    if (mesh < 0) continue;
    for (const glm::vec3& p : scene.meshes[size_t(mesh)].positions)
      bounds.include(glm::vec3(worldFromNode[i] * glm::vec4(p, 1.0f)));
  }
  return bounds;
}

}  // namespace qlight::scene
