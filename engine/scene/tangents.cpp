#include "engine/scene/tangents.h"

#include <cmath>

namespace qlight::scene {
namespace {

glm::vec3 anyPerpendicular(glm::vec3 n) {
  glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(axis, n));
}

}  // namespace

void generateTangents(MeshAsset& mesh, uint32_t uvSet) {
  const size_t n = mesh.positions.size();
  if (mesh.tangents.size() != n) mesh.tangents.assign(n, glm::vec4(0.0f));
  const std::vector<glm::vec2>& uv = uvSet == 1 && mesh.uv1.size() == n ? mesh.uv1 : mesh.uv0;
  std::vector<glm::vec3> dPdu(n, glm::vec3(0.0f)), dPdv(n, glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    const glm::vec3 e1 = mesh.positions[i1] - mesh.positions[i0];
    const glm::vec3 e2 = mesh.positions[i2] - mesh.positions[i0];
    const glm::vec2 d1 = uv[i1] - uv[i0], d2 = uv[i2] - uv[i0];
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 1e-20f)) continue;
    // Weighted by the triangle's area in UV space's inverse: dP/du and dP/dv as they are.
    const glm::vec3 u = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 v = (e2 * d1.x - e1 * d2.x) / det;
    if (!std::isfinite(u.x + u.y + u.z + v.x + v.y + v.z)) continue;
    for (uint32_t i : {i0, i1, i2}) {
      dPdu[i] += u;
      dPdv[i] += v;
    }
  }
  for (size_t i = 0; i < n; ++i) {
    if (mesh.tangents[i].w != 0.0f) continue;
    const glm::vec3 normal = mesh.normals[i];
    glm::vec3 t = dPdu[i] - normal * glm::dot(normal, dPdu[i]);
    const float len = glm::length(t);
    t = len > 1e-12f && std::isfinite(len) ? t / len : anyPerpendicular(normal);
    const float w = glm::dot(glm::cross(normal, t), dPdv[i]) > 0.0f ? -1.0f : 1.0f;
    mesh.tangents[i] = glm::vec4(t, w);
  }
}

void generateMissingTangents(SceneAsset& scene) {
  for (MeshAsset& mesh : scene.meshes) {
    int32_t uvSet = -1;
    for (uint32_t material : mesh.triangleMaterials) {
      const MaterialAsset& m = scene.materials[material];
      if (m.normalTexture.present()) {
        uvSet = int32_t(m.normalTexture.texCoord);
        break;
      }
    }
    if (uvSet < 0) continue;
    bool missing = mesh.tangents.size() != mesh.positions.size();
    for (const glm::vec4& t : mesh.tangents) missing |= t.w == 0.0f;
    if (missing) generateTangents(mesh, uint32_t(uvSet));
  }
}

}  // namespace qlight::scene
