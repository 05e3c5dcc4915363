// instantiate(), animationSystem() and transformSystem() on an ECS registry: one entity per
// node, hierarchy world transforms equal to the plain-data ones, dirty marks only for values
// that changed, a default camera when the scene has none.
#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include "engine/gltf/gltf_loader.h"
#include "engine/scene/animation.h"
#include "engine/scene/instantiate.h"
#include "engine/scene/procedural.h"
#include "engine/scene/transforms.h"
#include "tests/scene/matrix_compare.h"

namespace qlight::scene {
namespace {

using gltf::loadGltf;

// root (mesh) -> arm (animated rotation about y) -> hand (mesh, light); plus a static node.
SceneAsset armScene() {
  SceneAsset scene;
  scene.materials.push_back(MaterialAsset{});
  MeshAsset mesh;
  addBox(mesh, glm::mat4(1.0f), glm::vec3(0.5f), 0);
  scene.meshes.push_back(mesh);
  LightAsset light;
  light.type = LightType::Spot;
  light.intensity = 7.0f;
  scene.lights.push_back(light);

  NodeAsset root, arm, hand, still;
  root.name = "root";
  root.mesh = 0;
  root.local.translation = {0, 1, 0};
  arm.name = "arm";
  arm.local.translation = {2, 0, 0};
  hand.name = "hand";
  hand.mesh = 0;
  hand.light = 0;
  hand.local.translation = {1, 0, 0};
  still.name = "still";
  still.mesh = 0;
  still.local.translation = {-5, 0, 0};
  const uint32_t r = addNode(scene, root);
  const uint32_t a = addNode(scene, arm, int32_t(r));
  addNode(scene, hand, int32_t(a));
  addNode(scene, still);

  AnimationChannel spin;
  spin.node = a;
  spin.path = AnimationPath::Rotation;
  spin.interpolation = Interpolation::Linear;
  spin.times = {0, 1, 2};
  const float s = std::sqrt(0.5f);
  spin.values = {{0, 0, 0, 1}, {0, s, 0, s}, {0, 1, 0, 0}};  // 0, 90, 180 degrees about y
  AnimationAsset animation;
  animation.channels.push_back(spin);
  animation.duration = 2.0f;
  scene.animations.push_back(animation);
  refreshBounds(scene);
  return scene;
}

TEST(SceneSystems, InstantiateMakesOneEntityPerNodeWithItsComponents) {
  const SceneAsset scene = armScene();
  ecs::Registry registry;
  const InstantiatedScene made = instantiate(scene, registry);
  ASSERT_EQ(made.nodeEntities.size(), 4u);
  EXPECT_EQ(registry.aliveCount(), 5u);  // 4 nodes + the default camera
  EXPECT_TRUE(made.defaultCamera);

  const ecs::Entity root = made.nodeEntities[0], arm = made.nodeEntities[1],
                    hand = made.nodeEntities[2];
  EXPECT_EQ(registry.get<NodeName>(hand).name, "hand");
  EXPECT_EQ(registry.get<SceneNode>(hand).node, 2u);
  EXPECT_EQ(registry.get<Parent>(hand).entity, arm);
  EXPECT_EQ(registry.get<Parent>(arm).entity, root);
  EXPECT_FALSE(registry.has<Parent>(root));
  EXPECT_EQ(registry.get<MeshInstance>(hand).mesh, 0u);
  EXPECT_FALSE(registry.has<MeshInstance>(arm));
  EXPECT_EQ(registry.get<PunctualLight>(hand).type, LightType::Spot);
  EXPECT_EQ(registry.get<PunctualLight>(hand).intensity, 7.0f);
  EXPECT_TRUE(registry.has<AnimatedNode>(arm));
  EXPECT_EQ(registry.get<AnimatedNode>(arm).rotation.animation, 0u);
  EXPECT_FALSE(registry.get<AnimatedNode>(arm).translation.valid());
  EXPECT_FALSE(registry.has<AnimatedNode>(hand));
  EXPECT_TRUE(registry.has<Camera>(made.camera));

  // World transforms are ready: the hand sits at (0,1,0) + (2,0,0) + (1,0,0).
  const glm::vec3 handOrigin(registry.get<WorldTransform>(hand).worldFromLocal[3]);
  EXPECT_NEAR(glm::length(handOrigin - glm::vec3(3, 1, 0)), 0.0f, 1e-6f);
}

TEST(SceneSystems, SystemsMatchThePlainDataEvaluationAtAnyTime) {
  const SceneAsset scene = armScene();
  ecs::Registry registry;
  const InstantiatedScene made = instantiate(scene, registry);
  for (float t : {0.0f, 0.3f, 1.0f, 1.7f, 2.0f, 5.0f}) {
    animationSystem(registry, scene, t);
    transformSystem(registry);
    const std::vector<glm::mat4> expected = worldTransforms(scene, animate(scene, t));
    for (size_t i = 0; i < made.nodeEntities.size(); ++i)
      EXPECT_LT(maxDifference(registry.get<WorldTransform>(made.nodeEntities[i]).worldFromLocal,
                              expected[i]),
                1e-5f)
          << "node " << i << " t " << t;
  }
  // At 1 s the arm has turned 90 degrees about y: the hand's offset (1,0,0) becomes (0,0,-1).
  animationSystem(registry, scene, 1.0f);
  transformSystem(registry);
  const glm::vec3 hand(registry.get<WorldTransform>(made.nodeEntities[2]).worldFromLocal[3]);
  EXPECT_NEAR(glm::length(hand - glm::vec3(2, 1, -1)), 0.0f, 1e-5f);
}

TEST(SceneSystems, OnlyChangedComponentsAreMarkedDirty) {
  const SceneAsset scene = armScene();
  ecs::Registry registry;
  const InstantiatedScene made = instantiate(scene, registry);
  auto& locals = registry.storage<LocalTransform>();
  auto& worlds = registry.storage<WorldTransform>();

  animationSystem(registry, scene, 0.5f);
  transformSystem(registry);
  locals.clearDirty();
  worlds.clearDirty();

  // Same time again: nothing moves, nothing is dirty.
  animationSystem(registry, scene, 0.5f);
  transformSystem(registry);
  EXPECT_TRUE(locals.dirtyRange().empty());
  EXPECT_TRUE(worlds.dirtyRange().empty());

  // A new time: the arm's LocalTransform and the arm's and hand's WorldTransforms change;
  // root and the static node do not.
  animationSystem(registry, scene, 0.8f);
  transformSystem(registry);
  const ecs::Entity arm = made.nodeEntities[1], hand = made.nodeEntities[2],
                    still = made.nodeEntities[3], root = made.nodeEntities[0];
  EXPECT_TRUE(locals.dirtyRange().covers(locals.indexOf(arm)));
  EXPECT_EQ(locals.dirtyRange().size(), 1u);
  EXPECT_TRUE(worlds.dirtyRange().covers(worlds.indexOf(arm)));
  EXPECT_TRUE(worlds.dirtyRange().covers(worlds.indexOf(hand)));
  // Dirty ranges are contiguous; these two entities sit outside [arm, hand] in creation order.
  EXPECT_FALSE(worlds.dirtyRange().covers(worlds.indexOf(root)));
  EXPECT_FALSE(worlds.dirtyRange().covers(worlds.indexOf(still)));
}

TEST(SceneSystems, ParentsUpdateBeforeChildrenWhateverTheStorageOrder) {
  // Children created before their parents, and a three-level chain.
  ecs::Registry registry;
  const ecs::Entity leaf = registry.create();
  const ecs::Entity middle = registry.create();
  const ecs::Entity top = registry.create();
  LocalTransform offset;
  offset.translation = {1, 0, 0};
  for (ecs::Entity e : {leaf, middle, top}) {
    registry.emplace<LocalTransform>(e, offset);
    registry.emplace<WorldTransform>(e);
  }
  registry.emplace<Parent>(leaf, Parent{middle});
  registry.emplace<Parent>(middle, Parent{top});
  registry.patch<LocalTransform>(top, [](LocalTransform& l) { l.scale = glm::vec3(3.0f); });
  transformSystem(registry);
  // leaf = top(T(1,0,0) S(3)) * middle(T(1,0,0)) * leaf(T(1,0,0)) -> x = 1 + 3 * 2 = 7.
  EXPECT_NEAR(registry.get<WorldTransform>(leaf).worldFromLocal[3].x, 7.0f, 1e-6f);
  EXPECT_NEAR(registry.get<WorldTransform>(middle).worldFromLocal[3].x, 4.0f, 1e-6f);

  // A destroyed parent leaves a root behind.
  registry.destroy(top);
  transformSystem(registry);
  EXPECT_NEAR(registry.get<WorldTransform>(leaf).worldFromLocal[3].x, 2.0f, 1e-6f);
}

TEST(SceneSystems, ParentCyclesDoNotHang) {
  ecs::Registry registry;
  const ecs::Entity a = registry.create(), b = registry.create();
  for (ecs::Entity e : {a, b}) {
    registry.emplace<LocalTransform>(e);
    registry.emplace<WorldTransform>(e);
  }
  registry.emplace<Parent>(a, Parent{b});
  registry.emplace<Parent>(b, Parent{a});
  transformSystem(registry);  // returns; the result of a cycle is unspecified
  SUCCEED();
}

TEST(SceneSystems, FileCamerasAreUsedAndAnimatedSamplesMatch) {
  const SceneAsset cameras = loadGltf(std::filesystem::path(QLIGHT_SAMPLES_DIR) / "Cameras.gltf");
  ecs::Registry registry;
  const InstantiatedScene made = instantiate(cameras, registry);
  EXPECT_FALSE(made.defaultCamera);
  EXPECT_EQ(made.camera, made.nodeEntities[1]);
  EXPECT_NEAR(registry.get<Camera>(made.camera).yfov, 0.7f, 1e-6f);

  const SceneAsset boxes = loadGltf(std::filesystem::path(QLIGHT_SAMPLES_DIR) / "BoxAnimated.gltf");
  ecs::Registry r2;
  const InstantiatedScene box = instantiate(boxes, r2);
  EXPECT_TRUE(box.defaultCamera);
  for (float t : {0.0f, 1.0f, 2.4f, 3.0f, 4.0f}) {
    animationSystem(r2, boxes, t);
    transformSystem(r2);
    const std::vector<glm::mat4> expected = worldTransforms(boxes, animate(boxes, t));
    for (size_t i = 0; i < box.nodeEntities.size(); ++i)
      EXPECT_LT(
          maxDifference(r2.get<WorldTransform>(box.nodeEntities[i]).worldFromLocal, expected[i]),
          1e-5f);
  }
}

}  // namespace
}  // namespace qlight::scene
