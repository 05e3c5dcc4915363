// What tracking forgets by: the largest move of any light (an emissive mesh's bounds centre,
// or a punctual light) since the last frame over the scene's radius; other meshes moving,
// the first frame and a changed set of lights count nothing.
#include "engine/session/light_motion.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace qlight::session {
namespace {

scene::MeshAsset quad(uint32_t material) {
  scene::MeshAsset m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}};  // centre (1, 0, 1)
  m.indices = {0, 1, 2, 0, 2, 3};
  m.triangleMaterials = {material, material};
  return m;
}

TEST(LightMotion, TheLargestLightMoveOverTheSceneRadius) {
  scene::SceneAsset asset;
  asset.materials.resize(2);
  asset.materials[1].emissive = glm::vec3(5.0f);
  asset.meshes = {quad(0), quad(1)};  // mesh 1 emits
  LightMotion motion(asset);
  const float radius = 4.0f;
  auto draw = [](glm::mat4 wall, glm::mat4 lamp, std::vector<glm::vec3> punctual = {}) {
    render::SceneDraw d;
    d.meshes = {{0, wall}, {1, lamp}};
    for (glm::vec3 p : punctual) d.lights.push_back({{}, glm::translate(glm::mat4(1.0f), p)});
    return d;
  };
  const glm::mat4 id(1.0f);
  EXPECT_EQ(motion.update(draw(id, id), radius), 0.0f) << "nothing to compare the first time";
  EXPECT_EQ(motion.update(draw(glm::translate(id, {9, 0, 0}), id), radius), 0.0f)
      << "a mesh that does not emit moved";
  EXPECT_FLOAT_EQ(motion.update(draw(id, glm::translate(id, {0, 3, 0})), radius), 0.75f);
  // Shrinking about the origin moves the centre (1, 3, 1) to (0.5, 3, 0.5) (with the 3 up).
  const glm::mat4 shrunk = glm::translate(id, {0, 3, 0}) * glm::scale(id, glm::vec3(0.5f));
  EXPECT_NEAR(motion.update(draw(id, shrunk), radius), std::sqrt(0.5f) / radius, 1e-6f);
  EXPECT_EQ(motion.update(draw(id, shrunk, {{0, 0, 0}}), radius), 0.0f) << "a light was added";
  EXPECT_FLOAT_EQ(motion.update(draw(id, shrunk, {{0, 0, 2}}), radius), 0.5f);
}

}  // namespace
}  // namespace qlight::session
