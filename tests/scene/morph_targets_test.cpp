// Morph targets: a weight of 0.5 moves a vertex by half its target's offset, node weights
// override the mesh's, weights channels interpolate (linear, step, cubic spline) and drive the
// ECS, and the Khronos morph samples pose as their READMEs say.
#include <gtest/gtest.h>

#include <algorithm>

#include "engine/gltf/gltf_loader.h"
#include "engine/scene/animation.h"
#include "engine/scene/deform.h"
#include "engine/scene/instantiate.h"
#include "tests/gltf/gltf_doc_builder.h"

namespace qlight::scene {
namespace {

using gltf::testing::DocBuilder;
using gltf::testing::json;
using gltf::testing::TempDir;
using gltf::testing::writeDoc;

const std::filesystem::path kSamples = QLIGHT_SAMPLES_DIR;

// One triangle (normal +z) with one target that moves vertex 2 by d = (0, 0, 2) and turns
// its normal by (0, 1, -1); mesh weights [0.5], the node's `nodeWeights` when given.
json morphTriangle(json nodeWeights = nullptr) {
  DocBuilder b;
  const int positions = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int normals = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
  const int dp = b.addFloats({0, 0, 0, 0, 0, 0, 0, 0, 2}, "VEC3");
  const int dn = b.addFloats({0, 0, 0, 0, 0, 0, 0, 1, -1}, "VEC3");
  json node = {{"mesh", 0}};
  if (!nodeWeights.is_null()) node["weights"] = nodeWeights;
  return b.finish(
      {{"scene", 0},
       {"scenes", json::array({{{"nodes", {0}}}})},
       {"nodes", json::array({node})},
       {"meshes",
        json::array({{{"weights", {0.5}},
                      {"primitives",
                       json::array({{{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}},
                                     {"targets",
                                      json::array({{{"POSITION", dp}, {"NORMAL", dn}}})}}})}}})}});
}

TEST(MorphTargets, HalfWeightMovesAVertexByHalfItsOffset) {
  TempDir dir;
  const SceneAsset scene = gltf::loadGltf(writeDoc(dir, "morph.gltf", morphTriangle()));
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
  const MeshAsset& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.deform.targets.size(), 1u);
  EXPECT_EQ(mesh.positions[2], glm::vec3(0, 1, 1));  // d / 2
  const DeformedVertices half = deformMesh(mesh, std::vector<float>{0.5f}, {});
  EXPECT_EQ(half.positions[2], glm::vec3(0, 1, 1));
  EXPECT_EQ(half.positions[0], glm::vec3(0, 0, 0));
  // Normal (0, 0, 1) + 0.5 * (0, 1, -1) = (0, 0.5, 0.5), renormalized.
  EXPECT_NEAR(half.normals[2].y, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(half.normals[2].z, std::sqrt(0.5f), 1e-6f);
  const DeformedVertices full = deformMesh(mesh, std::vector<float>{1.0f}, {});
  EXPECT_EQ(full.positions[2], glm::vec3(0, 1, 2));
  EXPECT_NEAR(full.normals[2].y, 1.0f, 1e-6f);
  const DeformedVertices none = deformMesh(mesh, std::vector<float>{0.0f}, {});
  EXPECT_EQ(none.positions[2], glm::vec3(0, 1, 0));
}

TEST(MorphTargets, NodeWeightsOverrideTheMeshesInTheEcs) {
  TempDir dir;
  const SceneAsset scene = gltf::loadGltf(writeDoc(dir, "node.gltf", morphTriangle({0.25})));
  ecs::Registry registry;
  const InstantiatedScene made = instantiate(scene, registry);
  EXPECT_EQ(registry.get<MorphWeights>(made.nodeEntities[0]).weights, std::vector<float>{0.25f});
  transformSystem(registry);
  deformSystem(registry, scene);
  EXPECT_EQ(registry.get<DeformedMesh>(made.nodeEntities[0]).positions[2], glm::vec3(0, 1, 0.5f));
  EXPECT_NEAR(scene.bounds.max.z, 0.5f, 1e-6f);
}

AnimationChannel weightsChannel(Interpolation interpolation, std::vector<float> times,
                                std::vector<float> weights) {
  AnimationChannel c;
  c.path = AnimationPath::Weights;
  c.interpolation = interpolation;
  c.times = std::move(times);
  c.weights = std::move(weights);
  c.weightCount = 2;
  return c;
}

TEST(MorphTargets, WeightsChannelsInterpolateLinearStepAndCubic) {
  const AnimationChannel linear = weightsChannel(Interpolation::Linear, {0, 2}, {0, 1, 1, 0});
  EXPECT_EQ(sampleWeights(linear, 0.5f), (std::vector<float>{0.25f, 0.75f}));
  EXPECT_EQ(sampleWeights(linear, -1.0f), (std::vector<float>{0, 1}));  // clamped to the keys
  EXPECT_EQ(sampleWeights(linear, 3.0f), (std::vector<float>{1, 0}));
  const AnimationChannel step = weightsChannel(Interpolation::Step, {0, 2}, {0, 1, 1, 0});
  EXPECT_EQ(sampleWeights(step, 1.9f), (std::vector<float>{0, 1}));
  EXPECT_EQ(sampleWeights(step, 2.0f), (std::vector<float>{1, 0}));
  // Cubic: in-tangent, value, out-tangent per key (each 2 weights). Key values 0 and 1 with
  // zero tangents give the smoothstep 3u^2 - 2u^3 on weight 0; weight 1 has slope 1 per
  // second at both ends over a 2 s interval: p(u) = u (tangents scaled by dt = 2).
  const AnimationChannel cubic =
      weightsChannel(Interpolation::CubicSpline, {0, 2}, {0, 0, 0, 0, 0, 1, 0, 1, 1, 2, 0, 1});
  const std::vector<float> mid = sampleWeights(cubic, 1.0f);
  EXPECT_NEAR(mid[0], 0.5f, 1e-6f);
  EXPECT_NEAR(mid[1], 1.0f, 1e-6f);
  const std::vector<float> quarter = sampleWeights(cubic, 0.5f);
  EXPECT_NEAR(quarter[0], 3 * 0.0625f - 2 * 0.015625f, 1e-6f);
  EXPECT_NEAR(quarter[1], 0.5f, 1e-6f);
}

// SimpleMorph's weights are (0, 0) at 0 s, (0, 1) at 1 s, (1, 1) at 2 s: at 1.5 s (0.5, 1),
// so the apex (0.5, 0.5, 0) moves by 0.5 * (-1, 1, 0) + 1 * (1, 1, 0) to (1, 2, 0).
TEST(MorphTargets, SimpleMorphAtAKeyTimeFollowsItsWeightsChannel) {
  const SceneAsset scene = gltf::loadGltf(kSamples / "SimpleMorph.gltf");
  ecs::Registry registry;
  const InstantiatedScene made = instantiate(scene, registry);
  animationSystem(registry, scene, 1.5f);
  transformSystem(registry);
  deformSystem(registry, scene);
  EXPECT_EQ(registry.get<MorphWeights>(made.nodeEntities[0]).weights,
            (std::vector<float>{0.5f, 1.0f}));
  const std::vector<glm::vec3>& p = registry.get<DeformedMesh>(made.nodeEntities[0]).positions;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR(p[2].x, 1.0f, 1e-6f);
  EXPECT_NEAR(p[2].y, 2.0f, 1e-6f);
  EXPECT_EQ(animateWeights(scene, 1.5f)[0], (std::vector<float>{0.5f, 1.0f}));
}

// MorphPrimitivesTest: both primitives' targets raise a bump of 0.2; the mesh's weight 0.5
// raises it by 0.1 (a flat model means the targets were not applied).
TEST(MorphTargets, MorphPrimitivesTestRaisesBothPrimitivesAtHalfStrength) {
  const SceneAsset scene =
      gltf::loadGltf(kSamples / "features/MorphPrimitivesTest/glTF/MorphPrimitivesTest.gltf");
  ASSERT_EQ(scene.meshes.size(), 1u);
  const MeshAsset& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.deform.targets.size(), 1u);
  float top[2] = {0, 0};  // per material (red, green)
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const float y = mesh.positions[mesh.indices[3 * t + k]].y;
      float& m = top[mesh.triangleMaterials[t] == mesh.triangleMaterials[0] ? 0 : 1];
      m = std::max(m, y);
    }
  EXPECT_NEAR(top[0], 0.1f, 1e-6f);
  EXPECT_NEAR(top[1], 0.1f, 1e-6f);
}

TEST(MorphTargets, AnimatedMorphCubeChangesShapeOverTime) {
  const SceneAsset scene =
      gltf::loadGltf(kSamples / "features/AnimatedMorphCube/glTF/AnimatedMorphCube.gltf");
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
  ASSERT_EQ(scene.animations.size(), 1u);
  ecs::Registry registry;
  const InstantiatedScene made = instantiate(scene, registry);
  std::vector<std::vector<glm::vec3>> poses;
  for (float t : {0.0f, 1.0f, 3.0f}) {
    animationSystem(registry, scene, t);
    transformSystem(registry);
    deformSystem(registry, scene);
    poses.push_back(registry.get<DeformedMesh>(made.nodeEntities[0]).positions);
  }
  EXPECT_NE(poses[0], poses[1]);
  EXPECT_NE(poses[1], poses[2]);
}

}  // namespace
}  // namespace qlight::scene
