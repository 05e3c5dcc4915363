// How far the scene's lights moved since the last frame, as a share of the scene's radius:
// what tracking forgets by (guiding::GuidingSettings::forgetOnLightMove). A light is a mesh
// instance with an emissive triangle (its bounds' centre, so a light that grows or shrinks
// moves too) or a punctual light.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "engine/render/scene_draw.h"
#include "engine/scene/scene_asset.h"

namespace qlight::session {

class LightMotion {
 public:
  explicit LightMotion(const scene::SceneAsset& asset);
  // The largest move of any light since the last call over `sceneRadius`; 0 the first time
  // and when the set of lights changed.
  float update(const render::SceneDraw& draw, float sceneRadius);

 private:
  std::vector<glm::vec3> meshCentre_;  // object space, per mesh
  std::vector<bool> meshEmits_;
  std::vector<glm::vec3> last_;
  bool first_ = true;
};

}  // namespace qlight::session
