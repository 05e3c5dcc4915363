#include "engine/session/light_motion.h"

#include <algorithm>

namespace qlight::session {

LightMotion::LightMotion(const scene::SceneAsset& asset) {
  for (const scene::MeshAsset& m : asset.meshes) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    meshCentre_.push_back(m.positions.empty() ? glm::vec3(0.0f) : 0.5f * (lo + hi));
    bool emits = false;
    for (uint32_t material : m.triangleMaterials)
      emits |= material < asset.materials.size() && asset.materials[material].isEmissive();
    meshEmits_.push_back(emits);
  }
}

float LightMotion::update(const render::SceneDraw& draw, float sceneRadius) {
  std::vector<glm::vec3> now;
  for (const render::MeshDraw& d : draw.meshes)
    if (d.mesh < meshEmits_.size() && meshEmits_[d.mesh])
      now.push_back(glm::vec3(d.worldFromObject * glm::vec4(meshCentre_[d.mesh], 1.0f)));
  for (const render::PunctualDraw& l : draw.lights) now.push_back(glm::vec3(l.worldFromLight[3]));
  float moved = 0.0f;
  if (!first_ && now.size() == last_.size() && sceneRadius > 0.0f)
    for (size_t i = 0; i < now.size(); ++i)
      moved = std::max(moved, glm::length(now[i] - last_[i]) / sceneRadius);
  last_ = std::move(now);
  first_ = false;
  return moved;
}

}  // namespace qlight::session
