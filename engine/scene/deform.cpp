#include "engine/scene/deform.h"

#include <algorithm>
#include <cmath>

#include "engine/scene/animation.h"
#include "engine/scene/transforms.h"

namespace qlight::scene {
namespace {

glm::vec3 unitOr(glm::vec3 v, glm::vec3 fallback) {
  const float len = glm::length(v);
  return len > 1e-20f && std::isfinite(len) ? v / len : fallback;
}

void morph(const MeshDeformation& d, std::span<const float> weights, DeformedVertices& out) {
  out.positions = d.basePositions;
  out.normals = d.baseNormals;
  for (size_t t = 0; t < d.targets.size() && t < weights.size(); ++t) {
    const float w = weights[t];
    if (w == 0.0f) continue;
    const MorphTarget& target = d.targets[t];
    for (size_t i = 0; i < out.positions.size(); ++i) out.positions[i] += w * target.positions[i];
    for (size_t i = 0; i < target.normals.size(); ++i) out.normals[i] += w * target.normals[i];
  }
}

void skin(const MeshDeformation& d, std::span<const glm::mat4> joints, DeformedVertices& v) {
  const auto jointCount = uint32_t(joints.size());
  for (size_t i = 0; i < v.positions.size(); ++i) {
    glm::mat4 m(0.0f);
    for (int k = 0; k < 4; ++k) {
      const float w = d.weights[i][k];
      if (w != 0.0f && d.joints[i][k] < jointCount) m += w * joints[d.joints[i][k]];
    }
    if (m[3][3] == 0.0f) m = glm::mat4(1.0f);  // no weight at all (the loader warned)
    v.positions[i] = glm::vec3(m * glm::vec4(v.positions[i], 1.0f));
    // Normals by the inverse transpose of the blended matrix (renormalized later).
    const glm::mat3 linear(m);
    const float det = glm::determinant(linear);
    const glm::mat3 normalFrom = det != 0.0f ? glm::transpose(glm::inverse(linear)) : linear;
    v.normals[i] = normalFrom * v.normals[i];
  }
}

void flatNormals(const MeshAsset& mesh, DeformedVertices& v) {
  for (uint32_t t : mesh.deform.flatTriangles) {
    const uint32_t* tri = &mesh.indices[3 * size_t(t)];
    const glm::vec3 n = glm::cross(v.positions[tri[1]] - v.positions[tri[0]],
                                   v.positions[tri[2]] - v.positions[tri[0]]);
    for (int k = 0; k < 3; ++k) v.normals[tri[k]] = n;
  }
}

}  // namespace

std::vector<glm::mat4> jointMatrices(const SkinAsset& skin,
                                     const std::vector<glm::mat4>& worldFromNode) {
  std::vector<glm::mat4> out(skin.joints.size(), glm::mat4(1.0f));
  for (size_t j = 0; j < skin.joints.size(); ++j) {
    const glm::mat4 world =
        skin.joints[j] < worldFromNode.size() ? worldFromNode[skin.joints[j]] : glm::mat4(1.0f);
    out[j] = j < skin.inverseBindMatrices.size() ? world * skin.inverseBindMatrices[j] : world;
  }
  return out;
}

DeformedVertices deformMesh(const MeshAsset& mesh, std::span<const float> weights,
                            std::span<const glm::mat4> joints) {
  const MeshDeformation& d = mesh.deform;
  DeformedVertices v;
  if (d.morphed()) {
    morph(d, weights, v);
  } else {
    v.positions = mesh.positions;
    v.normals = mesh.normals;
  }
  if (!joints.empty() && d.skinnable()) skin(d, joints, v);
  flatNormals(mesh, v);
  for (size_t i = 0; i < v.normals.size(); ++i)
    v.normals[i] =
        unitOr(v.normals[i], i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0));
  return v;
}

std::vector<float> restWeights(const SceneAsset& scene, uint32_t node) {
  const NodeAsset& n = scene.nodes[node];
  if (n.mesh < 0) return {};
  const MeshDeformation& d = scene.meshes[size_t(n.mesh)].deform;
  std::vector<float> w = n.weights.empty() ? d.defaultWeights : n.weights;
  w.resize(d.targets.size(), 0.0f);
  return w;
}

std::vector<std::vector<float>> animateWeights(const SceneAsset& scene, float timeSeconds,
                                               bool loop) {
  std::vector<std::vector<float>> weights(scene.nodes.size());
  for (uint32_t n = 0; n < scene.nodes.size(); ++n) weights[n] = restWeights(scene, n);
  for (const AnimationAsset& animation : scene.animations) {
    const float t = animationTime(animation, timeSeconds, loop);
    for (const AnimationChannel& channel : animation.channels) {
      if (channel.path != AnimationPath::Weights || channel.node >= weights.size()) continue;
      std::vector<float> sampled = sampleWeights(channel, t);
      sampled.resize(weights[channel.node].size(), 0.0f);
      weights[channel.node] = std::move(sampled);
    }
  }
  return weights;
}

Bounds posedWorldBounds(const SceneAsset& scene, float timeSeconds) {
  const std::vector<glm::mat4> world = worldTransforms(scene, animate(scene, timeSeconds));
  const std::vector<std::vector<float>> weights = animateWeights(scene, timeSeconds);
  Bounds bounds;
  for (uint32_t n : nodesParentFirst(scene)) {
    const NodeAsset& node = scene.nodes[n];
    if (node.mesh < 0) continue;
    const MeshAsset& mesh = scene.meshes[size_t(node.mesh)];
    const bool skinned = node.skin >= 0 && mesh.deform.skinnable();
    std::vector<glm::mat4> joints;
    if (skinned) joints = jointMatrices(scene.skins[size_t(node.skin)], world);
    const bool deforms = skinned || mesh.deform.morphed();
    const std::vector<glm::vec3> posed =
        deforms ? deformMesh(mesh, weights[n], joints).positions : std::vector<glm::vec3>{};
    const std::vector<glm::vec3>& positions = deforms ? posed : mesh.positions;
    const glm::mat4 place = skinned ? glm::mat4(1.0f) : world[n];  // skins: world space
    if (skinned || node.instances.empty()) {
      for (const glm::vec3& p : positions) bounds.include(glm::vec3(place * glm::vec4(p, 1.0f)));
      continue;
    }
    // Many instances: each one's box of the mesh's box corners.
    Bounds local;
    for (const glm::vec3& p : positions) local.include(p);
    for (const LocalTransform& instance : node.instances) {
      const glm::mat4 m = place * toMatrix(instance);
      for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? local.max.x : local.min.x,
                               (c & 2) ? local.max.y : local.min.y,
                               (c & 4) ? local.max.z : local.min.z);
        bounds.include(glm::vec3(m * glm::vec4(corner, 1.0f)));
      }
    }
  }
  return bounds;
}

}  // namespace qlight::scene
