// TRS <-> matrix and world transforms of a node hierarchy (plain data, no ECS).
#include "engine/scene/transforms.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <random>

#include "engine/scene/procedural.h"
#include "tests/scene/matrix_compare.h"

namespace qlight::scene {
namespace {

TEST(Transforms, MatrixIsTranslationTimesRotationTimesScale) {
  LocalTransform local;
  local.translation = {1, 2, 3};
  local.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
  local.scale = {2, 3, 4};
  const glm::mat4 expected = glm::translate(glm::mat4(1.0f), local.translation) *
                             glm::mat4_cast(local.rotation) *
                             glm::scale(glm::mat4(1.0f), local.scale);
  EXPECT_LT(maxDifference(toMatrix(local), expected), 1e-6f);
}

TEST(Transforms, DecomposeInvertsComposeForRandomTrs) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    LocalTransform local;
    local.translation = {5 * u(rng), 5 * u(rng), 5 * u(rng)};
    local.rotation = glm::normalize(glm::quat(u(rng), u(rng), u(rng), u(rng)));
    local.scale = {0.1f + std::abs(u(rng)) * 3, 0.1f + std::abs(u(rng)) * 3,
                   (i % 2 ? -1.0f : 1.0f) * (0.1f + std::abs(u(rng)) * 3)};  // mirrored too
    const glm::mat4 m = toMatrix(local);
    EXPECT_LT(maxDifference(toMatrix(decompose(m)), m), 1e-4f) << "case " << i;
  }
}

// root: translate (1,0,0), rotate 90 degrees about z; child: translate (0,1,0), scale 2;
// grandchild: translate (1,0,0). Grandchild origin = root * (child * (1,0,0))
// = root * (2,1,0) = (1,0,0) + (-1,2,0) = (0,2,0).
TEST(Transforms, WorldTransformsFollowTheHierarchy) {
  SceneAsset scene;
  NodeAsset root, child, grandchild;
  root.local.translation = {1, 0, 0};
  root.local.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  child.local.translation = {0, 1, 0};
  child.local.scale = glm::vec3(2.0f);
  grandchild.local.translation = {1, 0, 0};
  const uint32_t r = addNode(scene, root);
  const uint32_t c = addNode(scene, child, int32_t(r));
  const uint32_t g = addNode(scene, grandchild, int32_t(c));
  const std::vector<glm::mat4> world = worldTransforms(scene, restPose(scene));
  const glm::vec3 origin(world[g][3]);
  EXPECT_NEAR(glm::length(origin - glm::vec3(0, 2, 0)), 0.0f, 1e-6f);
  // The grandchild's x axis: scaled by 2, turned to +y.
  EXPECT_NEAR(glm::length(glm::vec3(world[g][0]) - glm::vec3(0, 2, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(nodesParentFirst(scene), (std::vector<uint32_t>{r, c, g}));
}

TEST(Transforms, BoundsTransformEveryInstance) {
  SceneAsset scene;
  scene.materials.push_back(MaterialAsset{});
  MeshAsset mesh;
  addBox(mesh, glm::mat4(1.0f), glm::vec3(0.5f), 0);
  scene.meshes.push_back(mesh);
  NodeAsset a, b;
  a.mesh = b.mesh = 0;
  b.local.translation = {10, 0, 0};
  b.local.scale = {1, 4, 1};
  addNode(scene, a);
  addNode(scene, b);
  refreshBounds(scene);
  EXPECT_EQ(scene.bounds.min, glm::vec3(-0.5f, -2.0f, -0.5f));
  EXPECT_EQ(scene.bounds.max, glm::vec3(10.5f, 2.0f, 0.5f));
}

}  // namespace
}  // namespace qlight::scene
